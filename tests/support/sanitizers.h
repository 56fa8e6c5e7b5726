// Which sanitizer a test build runs under, for the tests that must know: GCC defines __SANITIZE_ADDRESS__ and
// __SANITIZE_THREAD__, clang 14 (the CI's ASan+UBSan build) answers only __has_feature. Each macro is 1 or 0.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#  define ROOMSENSE_TEST_ASAN 1
#elif defined(__has_feature)
#  if __has_feature(address_sanitizer)
#    define ROOMSENSE_TEST_ASAN 1
#  endif
#endif
#ifndef ROOMSENSE_TEST_ASAN
#  define ROOMSENSE_TEST_ASAN 0
#endif

#if defined(__SANITIZE_THREAD__)
#  define ROOMSENSE_TEST_TSAN 1
#elif defined(__has_feature)
#  if __has_feature(thread_sanitizer)
#    define ROOMSENSE_TEST_TSAN 1
#  endif
#endif
#ifndef ROOMSENSE_TEST_TSAN
#  define ROOMSENSE_TEST_TSAN 0
#endif

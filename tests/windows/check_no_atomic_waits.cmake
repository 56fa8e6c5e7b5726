# No shipped Windows binary may hold libstdc++'s atomic wait (std::__atomic_wait_address*): MinGW-w64's GCC 12
# implements it, without a futex, by a load, then a wait on a condition variable that a notify taking no lock can
# precede, so a waiter can sleep for ever. It comes in through std::stop_callback (a condition_variable_any's wait
# on a stop token), std::latch, std::barrier, the semaphores and std::atomic<T>::wait; the C API's worker hung in
# it under Wine in rs_analyzer_destroy. The code waits on std::condition_variable and its own flags instead.
# cmake -DNM=... -DBINARIES="a.dll;b.exe" -P check_no_atomic_waits.cmake
set(found)
foreach(binary IN LISTS BINARIES)
  execute_process(COMMAND ${NM} ${binary} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${binary}")
  endif()
  string(REGEX MATCHALL "[^\n]*__atomic_wait_address[^\n]*" hits "${out}")
  list(LENGTH hits n)
  if(n GREATER 0)
    list(GET hits 0 first)
    list(APPEND found "${binary}: ${n} symbols, e.g. ${first}")
  endif()
endforeach()
if(found)
  string(REPLACE ";" "\n  " listing "${found}")
  message(FATAL_ERROR "libstdc++'s atomic wait, which can hang on MinGW-w64, is in:\n  ${listing}")
endif()
list(LENGTH BINARIES checked)
message(STATUS "no atomic wait in the ${checked} binaries")

// Reads typed values from a fuzzer's bytes, front to back. Past the end every read gives 0 (or an empty span),
// so a harness never needs to check lengths: a short input simply decodes to zeros.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace roomsense::fuzz {

class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::size_t remaining() const { return size_ - pos_; }
  bool empty() const { return pos_ >= size_; }

  std::uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::uint16_t u16() { return static_cast<std::uint16_t>(u8() | (u8() << 8)); }
  std::uint32_t u32() { return static_cast<std::uint32_t>(u16()) | (static_cast<std::uint32_t>(u16()) << 16); }
  std::int8_t i8() { return static_cast<std::int8_t>(u8()); }
  std::int16_t i16() { return static_cast<std::int16_t>(u16()); }
  float f32() {
    const std::uint32_t bits = u32();
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
  }
  // A value in [0, n) (0 for n == 0).
  std::uint32_t below(std::uint32_t n) { return n == 0 ? 0 : u32() % n; }
  std::uint8_t below8(std::uint8_t n) { return n == 0 ? 0 : static_cast<std::uint8_t>(u8() % n); }

  // Up to n raw bytes (fewer at the end).
  std::string_view bytes(std::size_t n) {
    n = std::min(n, remaining());
    const std::string_view out(reinterpret_cast<const char*>(data_ + pos_), n);
    pos_ += n;
    return out;
  }
  std::string_view rest() { return bytes(remaining()); }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace roomsense::fuzz

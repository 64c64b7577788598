// FuzzInput: reads a fuzz input from the front, so that seed files stay readable: single bytes
// for choices, and chunks of bytes ended by a backslash followed by any character other than a
// backslash ("\\" stands for one backslash), like FuzzedDataProvider's random-length strings.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace armmimic::fuzz {

class FuzzInput {
 public:
  FuzzInput(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  bool empty() const { return pos_ >= size_; }
  uint8_t Byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  std::string Chunk(size_t max_len) {
    std::string out;
    while (pos_ < size_ && out.size() < max_len) {
      const char c = static_cast<char>(data_[pos_++]);
      if (c == '\\' && pos_ < size_) {
        const char next = static_cast<char>(data_[pos_++]);
        if (next != '\\') break;
      }
      out += c;
    }
    return out;
  }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

}  // namespace armmimic::fuzz

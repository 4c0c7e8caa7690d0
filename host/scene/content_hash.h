// A 64-bit hash of bytes, for identities (which scene a checkpoint belongs to) and corruption checks (a
// checkpoint's checksum): word at a time, about as fast as memory; not cryptographic.
#pragma once
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace vkmc {

class ContentHash {
 public:
  void add(const void* data, size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    size_t i = 0;
    for (; i + 8 <= bytes; i += 8) {
      uint64_t w;
      std::memcpy(&w, p + i, 8);
      mix(w);
    }
    uint64_t tail = 0;
    if (bytes > i) std::memcpy(&tail, p + i, bytes - i);
    mix(tail ^ (uint64_t(bytes) << 56));  // the length too: "ab" and "ab\0" differ
  }
  template <class T>
  void add(const std::vector<T>& v) {
    add(v.data(), v.size() * sizeof(T));
  }
  void add(const std::string& s) { add(s.data(), s.size()); }
  void addValue(uint64_t v) { add(&v, sizeof(v)); }
  uint64_t value() const {
    uint64_t h = h_;
    h ^= h >> 33, h *= 0xff51afd7ed558ccdull, h ^= h >> 33, h *= 0xc4ceb9fe1a85ec53ull, h ^= h >> 33;
    return h;
  }
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(value()));
    return buf;
  }

 private:
  void mix(uint64_t w) {
    w *= 0x87c37b91114253d5ull;
    w = (w << 31) | (w >> 33);
    w *= 0x4cf5ad432745937full;
    h_ ^= w;
    h_ = ((h_ << 27) | (h_ >> 37)) * 5 + 0x52dce729;
  }
  uint64_t h_ = 0x9e3779b97f4a7c15ull;
};

}  // namespace vkmc

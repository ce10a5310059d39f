// SHA-256 of pixel data and files (FIPS 180-4), so goldens carry exact fingerprints
// without another dependency.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace taa {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, size_t size);
  std::array<uint8_t, 32> finish();

 private:
  void block(const uint8_t* p);
  std::array<uint32_t, 8> state_;
  std::array<uint8_t, 64> buffer_{};
  size_t buffered_ = 0;
  uint64_t total_ = 0;
};

std::string sha256Hex(const void* data, size_t size);
std::string toHex(const uint8_t* bytes, size_t size);

}  // namespace taa

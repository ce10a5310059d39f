#include "golden/signature.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "core/image_io.h"

namespace taa::golden {

namespace {

constexpr int kCells = kSignatureGrid * kSignatureGrid;
constexpr size_t kLength = size_t(kCells) * 2 + 3 * 4;

const char* kHex = "0123456789abcdef";

void appendHex(std::string& out, unsigned value, int digits) {
  for (int d = digits - 1; d >= 0; --d) out += kHex[(value >> (4 * d)) & 0xfu];
}

bool parseHex(const std::string& s, size_t at, int digits, unsigned& value) {
  value = 0;
  for (int d = 0; d < digits; ++d) {
    const char c = s[at + size_t(d)];
    const int v = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
    if (v < 0) return false;
    value = value * 16 + unsigned(v);
  }
  return true;
}

}  // namespace

std::string frameSignature(const Image& hdr) {
  const Image d = toDisplaySrgb(hdr);
  // Sums in double in a fixed order: the signature is a function of the pixels alone.
  std::vector<double> cellSum(kCells, 0.0);
  std::vector<double> cellCount(kCells, 0.0);
  double channelSum[3] = {0.0, 0.0, 0.0};
  for (int y = 0; y < d.height; ++y) {
    const int row = y * kSignatureGrid / d.height;
    for (int x = 0; x < d.width; ++x) {
      const int cell = row * kSignatureGrid + x * kSignatureGrid / d.width;
      const double r = d.at(x, y, 0), g = d.at(x, y, 1), b = d.at(x, y, 2);
      cellSum[size_t(cell)] += 0.2126 * r + 0.7152 * g + 0.0722 * b;
      cellCount[size_t(cell)] += 1.0;
      channelSum[0] += r;
      channelSum[1] += g;
      channelSum[2] += b;
    }
  }
  std::string out;
  out.reserve(kLength);
  for (int c = 0; c < kCells; ++c) {
    // A frame narrower than the grid leaves cells empty; they read as black in both.
    const double mean = cellCount[size_t(c)] > 0 ? cellSum[size_t(c)] / cellCount[size_t(c)] : 0.0;
    appendHex(out, unsigned(std::lround(std::fmin(std::fmax(mean, 0.0), 1.0) * 255.0)), 2);
  }
  const double pixels = double(d.width) * double(d.height);
  for (double sum : channelSum) {
    const double mean = pixels > 0 ? sum / pixels : 0.0;
    appendHex(out, unsigned(std::lround(std::fmin(std::fmax(mean, 0.0), 1.0) * 65535.0)), 4);
  }
  return out;
}

SignatureDistance signatureDistance(const std::string& a, const std::string& b) {
  SignatureDistance out;
  if (a.size() != kLength || b.size() != kLength) return out;
  for (int c = 0; c < kCells; ++c) {
    unsigned va, vb;
    if (!parseHex(a, size_t(c) * 2, 2, va) || !parseHex(b, size_t(c) * 2, 2, vb)) return out;
    const int diff = std::abs(int(va) - int(vb));
    if (diff > out.cell) {
      out.cell = diff;
      out.cellIndex = c;
    }
  }
  for (int ch = 0; ch < 3; ++ch) {
    unsigned va, vb;
    const size_t at = size_t(kCells) * 2 + size_t(ch) * 4;
    if (!parseHex(a, at, 4, va) || !parseHex(b, at, 4, vb)) return out;
    out.mean = std::fmax(out.mean, std::fabs(double(va) - double(vb)) / 65535.0);
  }
  out.valid = true;
  return out;
}

}  // namespace taa::golden

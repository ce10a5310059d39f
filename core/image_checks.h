// Every length field of a PNG or OpenEXR file checked against the bytes present, before
// libpng or OpenEXR sees the file: both allocate what a field claims before finding out
// that the data is not there (a 1 KB PNG with a chunk length of 2^31, an EXR attribute
// of 0x7ffffff0 bytes each cost 2 GB). Messages name positions and field names, never
// the file's bytes.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace taa {

// "" when every chunk's length lies inside the file, IHDR comes first with 13 bytes and the
// chunks end with IEND or the file's end; else the first problem.
std::string pngStructureProblem(std::string_view bytes);

// What the first header of an OpenEXR file declares.
struct ExrHeaderInfo {
  std::vector<std::string> channels;  // in the file's order
  int64_t width = 0, height = 0;      // the data window
};

// "" when every attribute of every header lies inside the file, the first part's data
// window holds at most `maxSamples` samples and its offset table (8 bytes per chunk) fits
// in the bytes after the headers; else the first problem. Fills `info` from the first part.
std::string exrStructureProblem(std::string_view bytes, uint64_t maxSamples, ExrHeaderInfo& info);

}  // namespace taa

#include "core/png_codec.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/image_checks.h"

namespace taa::png {

// libpng reports errors by longjmp to the last setjmp. Every function below that can reach a
// longjmp holds only trivially destructible locals (C++ forbids jumping over destructors), so
// buffers live in the plain structs and the C++ wrappers own them.
namespace {

constexpr png_alloc_size_t kMaxPngChunkBytes = png_alloc_size_t(64) << 20;

struct PngCodecJob {
  char message[256] = "";
  // Reading.
  const unsigned char* input = nullptr;
  size_t inputSize = 0;
  size_t inputPos = 0;
  // Writing: a malloc'd buffer that grows, freed by the caller.
  unsigned char* output = nullptr;
  size_t outputSize = 0;
  size_t outputCapacity = 0;
};

void pngCodecError(png_structp png, png_const_charp text) {
  auto* job = static_cast<PngCodecJob*>(png_get_error_ptr(png));
  std::snprintf(job->message, sizeof(job->message), "%s", text ? text : "libpng error");
  // Jump ourselves: a handler that returns lets libpng's default one print "libpng error: ..." to
  // stderr first, next to the error the harness reports with the file's name.
  png_longjmp(png, 1);
}

// Warnings (an unusual sRGB profile, a bad CRC in an ancillary chunk) do not change the pixels.
void pngCodecWarning(png_structp, png_const_charp) {}

void pngCodecRead(png_structp png, png_bytep out, size_t count) {
  auto* job = static_cast<PngCodecJob*>(png_get_io_ptr(png));
  if (count > job->inputSize - job->inputPos) png_error(png, "the file ends early (truncated)");
  std::memcpy(out, job->input + job->inputPos, count);
  job->inputPos += count;
}

void pngCodecWrite(png_structp png, png_bytep data, size_t count) {
  auto* job = static_cast<PngCodecJob*>(png_get_io_ptr(png));
  if (count > job->outputCapacity - job->outputSize) {
    size_t capacity = job->outputCapacity ? job->outputCapacity * 2 : 65536;
    while (capacity - job->outputSize < count) capacity *= 2;
    void* grown = std::realloc(job->output, capacity);
    if (!grown) png_error(png, "out of memory");
    job->output = static_cast<unsigned char*>(grown);
    job->outputCapacity = capacity;
  }
  std::memcpy(job->output + job->outputSize, data, count);
  job->outputSize += count;
}

void pngCodecFlush(png_structp) {}

struct PngShape {
  uint32_t width = 0, height = 0;
  int channels = 0, bitDepth = 0;
  size_t rowBytes = 0;
};

// Reads the header and sets up the conversions to 8- or 16-bit grey/GA/RGB/RGBA.
bool pngReadHeader(png_structp png, png_infop info, PngShape* shape) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  const int colour = png_get_color_type(png, info);
  const int depth = png_get_bit_depth(png, info);
  if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (colour == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  if (depth == 16) png_set_swap(png);  // native-endian 16-bit samples (x86 and ARM)
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  shape->width = png_get_image_width(png, info);
  shape->height = png_get_image_height(png, info);
  shape->channels = png_get_channels(png, info);
  shape->bitDepth = png_get_bit_depth(png, info);
  shape->rowBytes = png_get_rowbytes(png, info);
  return true;
}

bool pngReadRows(png_structp png, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, nullptr);
  return true;
}

bool pngWriteAll(png_structp png, png_infop info, png_bytepp rows, int width, int height,
                 int channels, int level) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8,
               channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, level);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

bool hasPngSignature(std::string_view bytes) {
  return bytes.size() >= 8 &&
         png_sig_cmp(reinterpret_cast<png_const_bytep>(bytes.data()), 0, 8) == 0;
}

std::string encode8(const uint8_t* samples, int width, int height, int channels, int zlibLevel) {
  if (width <= 0 || height <= 0 || (channels != 1 && channels != 3))
    throw PngError("cannot encode a " + std::to_string(width) + "x" + std::to_string(height) +
                   " image with " + std::to_string(channels) + " channels");
  PngCodecJob job;
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, &job, pngCodecError, pngCodecWarning);
  if (!png) throw PngError("libpng could not start (out of memory)");
  png_infop info = png_create_info_struct(png);
  png_set_write_fn(png, &job, pngCodecWrite, pngCodecFlush);
  std::vector<png_bytep> rows(static_cast<size_t>(height));
  const size_t stride = size_t(width) * size_t(channels);
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = const_cast<png_bytep>(samples + y * stride);
  const bool ok = info && pngWriteAll(png, info, rows.data(), width, height, channels, zlibLevel);
  png_destroy_write_struct(&png, &info);
  std::string out;
  if (ok) out.assign(reinterpret_cast<const char*>(job.output), job.outputSize);
  std::free(job.output);
  if (!ok) throw PngError(job.message[0] ? job.message : "libpng could not start");
  return out;
}

Image decode(std::string_view bytes, uint64_t maxSamples) {
  if (!hasPngSignature(bytes)) throw PngError("not a PNG file (no PNG signature)");
  if (const std::string why = pngStructureProblem(bytes); !why.empty()) throw PngError(why);
  PngCodecJob job;
  job.input = reinterpret_cast<const unsigned char*>(bytes.data());
  job.inputSize = bytes.size();
  png_structp png =
      png_create_read_struct(PNG_LIBPNG_VER_STRING, &job, pngCodecError, pngCodecWarning);
  if (!png) throw PngError("libpng could not start (out of memory)");
  png_infop info = png_create_info_struct(png);
  png_set_read_fn(png, &job, pngCodecRead);
  // Compressed ancillary chunks (iCCP, zTXt, iTXt) inflate: bound what one may become.
  png_set_chunk_malloc_max(png, kMaxPngChunkBytes);
  PngShape shape;
  bool ok = info && pngReadHeader(png, info, &shape);
  const uint64_t samples = uint64_t(shape.width) * shape.height * uint64_t(shape.channels);
  if (ok && samples > maxSamples) {
    png_destroy_read_struct(&png, &info, nullptr);
    throw PngError("is " + std::to_string(shape.width) + "x" + std::to_string(shape.height) +
                   " with " + std::to_string(shape.channels) + " channels, over the limit of " +
                   std::to_string(maxSamples) + " samples");
  }
  std::vector<unsigned char> raw;
  std::vector<png_bytep> rows;
  if (ok) {
    raw.resize(shape.rowBytes * shape.height);
    rows.resize(shape.height);
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = raw.data() + y * shape.rowBytes;
    ok = pngReadRows(png, rows.data());
  }
  png_destroy_read_struct(&png, &info, nullptr);
  if (!ok) throw PngError(job.message[0] ? job.message : "libpng could not start");

  Image image(int(shape.width), int(shape.height), shape.channels);
  if (shape.bitDepth == 16) {
    for (size_t i = 0; i < image.data.size(); ++i) {
      uint16_t v;
      std::memcpy(&v, raw.data() + 2 * i, 2);
      image.data[i] = float(v) * (1.0f / 65535.0f);
    }
  } else {
    for (size_t i = 0; i < image.data.size(); ++i) image.data[i] = float(raw[i]) * (1.0f / 255.0f);
  }
  return image;
}

}  // namespace taa::png

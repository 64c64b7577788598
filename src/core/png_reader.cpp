#include "png_reader.h"

#include <csetjmp>
#include <cstring>
#include <vector>

#include <png.h>

namespace armmimic::internal {
namespace {

// libpng reports errors through longjmp; the message is kept here on the way out.
void OnPngError(png_structp png, png_const_charp message) {
  auto* error = static_cast<std::string*>(png_get_error_ptr(png));
  if (error) *error = message ? message : "corrupt PNG data";
  png_longjmp(png, 1);
}

void OnPngWarning(png_structp, png_const_charp) {}

// The encoded bytes libpng reads from.
struct Source {
  const unsigned char* data;
  std::size_t size;
  std::size_t at;
};

void ReadFromSource(png_structp png, png_bytep out, png_size_t length) {
  auto* source = static_cast<Source*>(png_get_io_ptr(png));
  if (length > source->size - source->at) png_error(png, "the file ends inside the image");
  std::memcpy(out, source->data + source->at, length);
  source->at += length;
}

// Larger images are refused before their pixels are allocated: a damaged header must not ask for
// gigabytes. A camera's frame is far below either bound.
constexpr png_uint_32 kMaxSide = 1 << 15;
constexpr double kMaxPixels = 1 << 27;

// The decode proper, apart so that nothing with a destructor lives across setjmp.
bool Decode(Source* source, cv::Mat* out, std::string* error) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, error, OnPngError, OnPngWarning);
  if (!png) {
    *error = "out of memory";
    return false;
  }
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    *error = "out of memory";
    return false;
  }
  // Rows are decoded into `image`, allocated before setjmp so a longjmp leaves nothing behind.
  cv::Mat* image = out;
  std::vector<png_bytep>* rows = new std::vector<png_bytep>();
  volatile bool ok = false;
  if (setjmp(png_jmpbuf(png)) == 0) {
    png_set_read_fn(png, source, ReadFromSource);
    png_set_user_limits(png, kMaxSide, kMaxSide);
    png_read_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info);
    const png_uint_32 height = png_get_image_height(png, info);
    if (static_cast<double>(width) * height > kMaxPixels) png_error(png, "image too large");
    const int depth = png_get_bit_depth(png, info);
    const int colour = png_get_color_type(png, info);
    if (colour == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (colour == PNG_COLOR_TYPE_GRAY && depth < 8) png_set_expand_gray_1_2_4_to_8(png);
    if ((colour & PNG_COLOR_MASK_ALPHA) != 0) png_set_strip_alpha(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) {
      // Transparency becomes an alpha channel in libpng's expansion; drop it as well.
      png_set_tRNS_to_alpha(png);
      png_set_strip_alpha(png);
    }
    if (colour == PNG_COLOR_TYPE_GRAY || colour == PNG_COLOR_TYPE_GRAY_ALPHA) {
      png_set_gray_to_rgb(png);
    }
    png_set_bgr(png);
    if (depth == 16) png_set_swap(png);  // host order for the 16-bit samples read below
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const int type = depth == 16 ? CV_16UC3 : CV_8UC3;
    image->create(static_cast<int>(height), static_cast<int>(width), type);
    rows->resize(height);
    for (png_uint_32 y = 0; y < height; ++y) (*rows)[y] = image->ptr(static_cast<int>(y));
    png_read_image(png, rows->data());
    png_read_end(png, nullptr);
    ok = true;
  }
  png_destroy_read_struct(&png, &info, nullptr);
  delete rows;
  return ok;
}

}  // namespace

bool IsPng(const unsigned char* data, std::size_t size) {
  return size >= 8 && png_sig_cmp(data, 0, 8) == 0;
}

bool DecodePng(const unsigned char* data, std::size_t size, cv::Mat* bgr, std::string* error) {
  if (!IsPng(data, size)) {
    *error = "not a PNG file";
    return false;
  }
  Source source{data, size, 0};
  cv::Mat image;
  if (!Decode(&source, &image, error)) return false;
  if (image.depth() == CV_16U) image.convertTo(image, CV_8UC3, 1 / 257.0);
  *bgr = image;
  return true;
}

}  // namespace armmimic::internal

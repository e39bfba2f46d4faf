#include "png_writer.hpp"

#include <png.h>

#include <algorithm>
#include <limits>
#include <string>

#include "host_errors.hpp"

namespace peristep::host {

std::uint64_t pictureBlockSize(std::uint64_t nx) {
  if (nx == 0) return 1;
  return std::max<std::uint64_t>(1, (kMinimumPictureWidth + nx - 1) / nx);
}

void writePng(const std::filesystem::path& file, const RgbImage& image) {
  if (image.nx == 0 || image.ny == 0 || image.pixels.size() != image.nx * image.ny)
    throw RunError(file.string() + ": no picture to write (the image is empty or its size does not match its shape)");
  const std::uint64_t k = pictureBlockSize(image.nx);
  const std::uint64_t width = image.nx * k, height = image.ny * k;
  if (width * 3 > std::numeric_limits<png_int_32>::max() || height > std::numeric_limits<png_uint_32>::max())
    throw RunError(file.string() + ": the picture would be too large for a PNG");

  // libpng's simplified API reports errors through png_image::message instead of longjmp, which
  // must not cross C++ frames. Its buffer is top-down, so picture row 0 is the grid's last row.
  std::vector<std::uint8_t> buffer(width * height * 3);
  for (std::uint64_t py = 0; py < height; ++py) {
    const std::uint64_t row = image.ny - 1 - py / k;
    std::uint8_t* out = buffer.data() + py * width * 3;
    for (std::uint64_t px = 0; px < width; ++px) {
      const Rgb& c = image.at(row, px / k);
      *out++ = c.r;
      *out++ = c.g;
      *out++ = c.b;
    }
  }

  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(width);
  png.height = static_cast<png_uint_32>(height);
  png.format = PNG_FORMAT_RGB;
  const int ok = png_image_write_to_file(&png, file.c_str(), 0, buffer.data(), static_cast<png_int_32>(width * 3), nullptr);
  const std::string message = png.message;
  png_image_free(&png);
  if (!ok) throw RunError(file.string() + ": cannot write the PNG: " + message);
}

}  // namespace peristep::host

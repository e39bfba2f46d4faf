// The damage picture of `peristep run`: the PNG writer and colour map read back with libpng, and the
// picture a small glass-ceramic run leaves next to its results.
#include <catch2/catch.hpp>

#include <png.h>

#include "damage_picture.hpp"
#include "host_errors.hpp"
#include "host_test_support.hpp"
#include "png_writer.hpp"

using namespace host_test;
using namespace peristep::host;
using Catch::Matchers::Contains;

namespace {

// A PNG decoded to 8-bit RGB, picture row 0 at the top as in the file.
struct Picture {
  std::uint32_t width = 0, height = 0;
  bool colour = false, alpha = false;  // as stored in the file, before conversion to RGB
  std::vector<std::uint8_t> rgb;
  Rgb at(std::uint32_t x, std::uint32_t y) const {
    const std::uint8_t* p = rgb.data() + (static_cast<std::size_t>(y) * width + x) * 3;
    return {p[0], p[1], p[2]};
  }
};

Picture readPng(const fs::path& file) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, file.c_str())) throw std::runtime_error(file.string() + ": " + image.message);
  Picture p;
  p.width = image.width;
  p.height = image.height;
  p.colour = image.format & PNG_FORMAT_FLAG_COLOR;
  p.alpha = image.format & PNG_FORMAT_FLAG_ALPHA;
  image.format = PNG_FORMAT_RGB;
  p.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, p.rgb.data(), 0, nullptr)) {
    const std::string message = image.message;
    png_image_free(&image);
    throw std::runtime_error(file.string() + ": " + message);
  }
  return p;
}

// The colour at the centre of grid point (row, col)'s block, row 0 being the bottom of the picture.
Rgb pointColour(const Picture& p, std::uint64_t ny, std::uint64_t row, std::uint64_t col, std::uint64_t k) {
  return p.at(static_cast<std::uint32_t>(col * k + k / 2), static_cast<std::uint32_t>((ny - 1 - row) * k + k / 2));
}

}  // namespace

namespace peristep::host {
std::ostream& operator<<(std::ostream& os, const Rgb& c) {
  return os << '(' << int(c.r) << ", " << int(c.g) << ", " << int(c.b) << ')';
}
}  // namespace peristep::host

TEST_CASE("png: each grid point becomes a block wide enough for an 800 px picture", "[host][png]") {
  CHECK(pictureBlockSize(26) == 31);  // 806 px
  CHECK(pictureBlockSize(51) == 16);  // 816 px
  CHECK(pictureBlockSize(400) == 2);
  CHECK(pictureBlockSize(401) == 2);
  CHECK(pictureBlockSize(800) == 1);
  CHECK(pictureBlockSize(1601) == 1);
}

TEST_CASE("png: phases by Young's modulus, cracks over them", "[host][png]") {
  // One row: glass, crystal, glass just below the crack threshold, crystal at it, fully broken glass.
  const std::vector<double> E{80e9, 133e9, 80e9, 133e9, 80e9};
  const std::vector<double> d{0.0, 0.2, kCrackDamage - 0.01, kCrackDamage, 1.0};
  const RgbImage image = damagePicture(1, 5, d, E);
  CHECK(image.at(0, 0) == kSoftPhase);
  CHECK(image.at(0, 1) == kStiffPhase);
  CHECK(image.at(0, 2) == kSoftPhase);
  CHECK(image.at(0, 3) == kCrackOnset);
  CHECK(image.at(0, 4) == kCrackFull);

  // More damage is brighter; a uniform material, or none known, is the middle blue.
  const RgbImage ramp = damagePicture(1, 3, {0.5, 0.75, 0.95}, {});
  const auto brightness = [](const Rgb& c) { return int(c.r) + c.g + c.b; };
  CHECK(brightness(ramp.at(0, 0)) < brightness(ramp.at(0, 1)));
  CHECK(brightness(ramp.at(0, 1)) < brightness(ramp.at(0, 2)));
  CHECK(damagePicture(1, 2, {0, 0}, {133e9, 133e9}).pixels == std::vector<Rgb>(2, kUniformPhase));
  CHECK(damagePicture(1, 2, {0, 0}, {}).pixels == std::vector<Rgb>(2, kUniformPhase));
  // The midpoint of the range splits the phases, whatever the two values are.
  const RgbImage split = damagePicture(1, 3, {0, 0, 0}, {1.0, 2.0, 1.6});
  CHECK(split.at(0, 2) == kStiffPhase);

  CHECK_THROWS_AS(damagePicture(2, 2, {0, 0, 0}, {}), RunError);
  CHECK_THROWS_AS(damagePicture(1, 2, {0, 0}, {1.0}), RunError);
}

TEST_CASE("png: a written picture reads back with row 0 at the bottom", "[host][png]") {
  TempDir dir;
  // ny = 3, nx = 4: a crack along the bottom row's left half, a crystal in the top right corner.
  std::vector<double> E(12, 80e9), d(12, 0.0);
  E[2 * 4 + 3] = 133e9;
  d[0 * 4 + 0] = 1.0;
  d[0 * 4 + 1] = 0.5;
  const fs::path file = dir / "picture.png";
  writePng(file, damagePicture(3, 4, d, E));

  const Picture p = readPng(file);
  const std::uint64_t k = pictureBlockSize(4);
  REQUIRE(k == 200);
  CHECK(p.width == 800);
  CHECK(p.height == 600);
  CHECK(p.colour);
  CHECK_FALSE(p.alpha);

  CHECK(pointColour(p, 3, 0, 0, k) == kCrackFull);         // damaged point
  CHECK(p.at(0, p.height - 1) == kCrackFull);               // ... whose block holds the bottom-left corner
  CHECK(p.at(k - 1, p.height - k) == kCrackFull);           // ... and is k x k
  CHECK(p.at(k, p.height - 1) != kCrackFull);
  CHECK(p.at(0, p.height - 1 - k) == kSoftPhase);
  CHECK(pointColour(p, 3, 2, 3, k) == kStiffPhase);         // intact crystal point
  CHECK(p.at(p.width - 1, 0) == kStiffPhase);               // ... in the top-right corner
  CHECK(pointColour(p, 3, 2, 0, k) == kSoftPhase);          // top left: intact glass, not the crack
  const Rgb half = pointColour(p, 3, 0, 1, k);
  CHECK(half.r > half.b);                                   // damage 0.5 is drawn as crack, not as material
}

TEST_CASE("png: an unwritable picture is a RunError", "[host][png]") {
  TempDir dir;
  const RgbImage image = damagePicture(1, 1, {0.0}, {});
  CHECK_THROWS_AS(writePng(dir / "no_such_dir" / "p.png", image), RunError);
  CHECK_THROWS_AS(writePng(dir / "empty.png", RgbImage{}), RunError);
}

TEST_CASE("png: the run's picture needs both damage and youngsModulus on the grid", "[host][png]") {
  TempDir dir;
  ResultLayout layout;
  layout.ny = 2;
  layout.nx = 3;
  layout.fields = {{"ux", {2, 3}, "m", ""}, {"damage", {2, 3}, "", ""}};
  StepValues step;
  step.fields = {std::vector<double>(6, 0.0), std::vector<double>(6, 0.0)};
  CHECK_FALSE(writeDamagePicture(dir / "a.png", layout, step));
  CHECK_FALSE(fs::exists(dir / "a.png"));

  layout.fields.push_back({"youngsModulus", {6}, "Pa", ""});  // not on the grid
  step.fields.push_back(std::vector<double>(6, 80e9));
  CHECK_FALSE(writeDamagePicture(dir / "b.png", layout, step));

  layout.fields.back().shape = {2, 3};
  CHECK(writeDamagePicture(dir / "c.png", layout, step) == dir / "c.png");
  const Picture p = readPng(dir / "c.png");
  CHECK(p.width == 3 * pictureBlockSize(3));
  CHECK(p.height == 2 * pictureBlockSize(3));
  CHECK(p.at(0, 0) == kUniformPhase);
}

TEST_CASE("peristep run: a glass-ceramic run leaves a damage picture next to its results", "[host][png][run]") {
  TempDir dir;
  const ProcessResult r =
      runProcess({PERISTEP_HOST_BINARY, "run", PERISTEP_HOST_TEST_DATA "/glass_ceramic_small.toml", "--out", "small.h5"},
                 dir.path());
  INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  REQUIRE(r.exitCode == 0);
  CHECK_THAT(r.out, Contains("wrote small.h5 (3 steps, 14 x 26 points), small.xmf and small.png"));
  REQUIRE(fs::exists(dir / "small.png"));

  const Picture p = readPng(dir / "small.png");
  CHECK(p.width == 26 * 31);
  CHECK(p.height == 14 * 31);
  CHECK(p.colour);
  // The plate has both phases.
  bool glass = false, crystal = false;
  for (std::uint32_t y = 0; y < p.height; ++y)
    for (std::uint32_t x = 0; x < p.width; ++x) glass |= p.at(x, y) == kSoftPhase, crystal |= p.at(x, y) == kStiffPhase;
  CHECK(glass);
  CHECK(crystal);
  // The 100 um pre-crack enters from the left edge at mid-height: its faces are drawn as crack.
  const Rgb precrack = p.at(p.width / 100, p.height / 2);
  CHECK(precrack.r > precrack.b);
}

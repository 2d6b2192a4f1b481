// Hostile inputs through the scene module's loaders: PNGs built byte by byte (truncated,
// empty, 1x1, huge sizes in the header, 16-bit, grey, grey + alpha, palette with and without
// transparency and with indices past the palette, other formats), scene files that are too
// big, too deep, too bright or ask for too many triangles, special files (/dev/zero, a
// directory), OBJ files in UTF-16, with CR line ends, with material names holding spaces, and
// over their triangle budget. Every refusal is an InputError whose message starts with the
// file's name; every expected pixel is worked out by hand from the PNG specification.
#include "scene/errors.h"
#include "scene/image.h"
#include "scene/obj_loader.h"
#include "scene/scene_file.h"
#include "scene/texture.h"
#include "scene/work_counters.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <array>
#include <cmath>
#include <sstream>
#include <tuple>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

namespace twr {
namespace {

// Work done so far in this process (scene/work_counters.h): the complexity guards below count
// work instead of timing it.
std::uint64_t decodedImages() { return workCounters().imagesDecoded.load(); }
std::uint64_t jsonValuesBuilt() { return workCounters().jsonValuesBuilt.load(); }
std::uint64_t meshesBuilt() { return workCounters().meshesBuilt.load(); }

namespace fs = std::filesystem;

using Bytes = std::vector<std::uint8_t>;

// ---- files under the test output folder ----

fs::path caseDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(TWINRASTER_TEST_OUT) / "hostile" / (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string writeFile(const fs::path& path, const Bytes& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return path.string();
}

std::string writeText(const fs::path& path, const std::string& text) {
  return writeFile(path, Bytes(text.begin(), text.end()));
}

// The InputError message `f` throws; a test failure when it throws nothing.
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

void expectStartsWith(const std::string& message, const std::string& start) {
  EXPECT_EQ(message.rfind(start, 0), 0u) << "\"" << message << "\" does not start with \"" << start << "\"";
}

void expectContains(const std::string& message, std::initializer_list<std::string> parts) {
  for (const std::string& part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "missing \"" << part << "\" in: " << message;
  }
}

// ---- PNG files built byte by byte (PNG specification, ISO/IEC 15948) ----

void appendBigEndian32(Bytes& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

std::uint32_t crc32(const Bytes& data, std::size_t begin) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = begin; i < data.size(); ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

void appendChunk(Bytes& png, const char* type, const Bytes& data) {
  appendBigEndian32(png, static_cast<std::uint32_t>(data.size()));
  const std::size_t typeAt = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  appendBigEndian32(png, crc32(png, typeAt));
}

// A zlib stream of "stored" (uncompressed) deflate blocks: header 0x78 0x01, blocks of at
// most 65535 bytes (BFINAL flag, LEN, ~LEN little-endian), Adler-32 big-endian.
Bytes zlibStored(const Bytes& raw) {
  Bytes out{0x78, 0x01};
  std::size_t at = 0;
  do {
    const std::size_t length = std::min<std::size_t>(raw.size() - at, 65535);
    out.push_back(at + length == raw.size() ? 1 : 0);
    out.push_back(static_cast<std::uint8_t>(length));
    out.push_back(static_cast<std::uint8_t>(length >> 8));
    out.push_back(static_cast<std::uint8_t>(~length));
    out.push_back(static_cast<std::uint8_t>(~length >> 8));
    out.insert(out.end(), raw.begin() + static_cast<std::ptrdiff_t>(at), raw.begin() + static_cast<std::ptrdiff_t>(at + length));
    at += length;
  } while (at < raw.size());
  std::uint32_t a = 1, b = 0;
  for (std::uint8_t byte : raw) {
    a = (a + byte) % 65521;
    b = (b + a) % 65521;
  }
  appendBigEndian32(out, (b << 16) | a);
  return out;
}

enum ColourType : std::uint8_t { kGrey = 0, kRgb = 2, kPalette = 3, kGreyAlpha = 4, kRgba = 6 };

struct PngSpec {
  std::uint32_t width = 1, height = 1;
  std::uint8_t bitDepth = 8;
  ColourType colourType = kRgba;
  std::vector<Bytes> rows;  // each row's bytes, without the filter byte (filter 0 is added)
  Bytes palette;            // PLTE data (RGB triples), only when non-empty
  Bytes transparency;       // tRNS data, only when non-empty
};

Bytes makePng(const PngSpec& spec) {
  Bytes png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  Bytes header;
  appendBigEndian32(header, spec.width);
  appendBigEndian32(header, spec.height);
  header.insert(header.end(), {spec.bitDepth, spec.colourType, 0, 0, 0});  // deflate, adaptive filters, no interlace
  appendChunk(png, "IHDR", header);
  if (!spec.palette.empty()) appendChunk(png, "PLTE", spec.palette);
  if (!spec.transparency.empty()) appendChunk(png, "tRNS", spec.transparency);
  Bytes raw;
  for (const Bytes& row : spec.rows) {
    raw.push_back(0);  // filter type None
    raw.insert(raw.end(), row.begin(), row.end());
  }
  appendChunk(png, "IDAT", zlibStored(raw));
  appendChunk(png, "IEND", {});
  return png;
}

std::array<int, 4> pixelOf(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2], p[3]};
}

// A valid 4x2 RGBA image, every byte distinct.
PngSpec rgba4x2() {
  PngSpec spec;
  spec.width = 4;
  spec.height = 2;
  for (std::uint8_t y = 0; y < 2; ++y) {
    Bytes row;
    for (std::uint8_t i = 0; i < 16; ++i) row.push_back(static_cast<std::uint8_t>(16 * y + i));
    spec.rows.push_back(row);
  }
  return spec;
}

// ---- PNGs ----

TEST(HostilePng, ValidRgbaLoadsTopRowFirst) {
  const std::string path = writeFile(caseDir() / "rgba.png", makePng(rgba4x2()));
  const Image image = loadPng(path);
  ASSERT_EQ(image.width, 4);
  ASSERT_EQ(image.height, 2);
  EXPECT_EQ(pixelOf(image, 0, 0), (std::array<int, 4>{0, 1, 2, 3}));
  EXPECT_EQ(pixelOf(image, 3, 1), (std::array<int, 4>{28, 29, 30, 31}));
  // As a texture, row 0 is the bottom row of the file.
  const Texture texture = loadTexture(path);
  EXPECT_EQ(texture.texel(0, 0)[0], 16);
  EXPECT_EQ(texture.texel(0, 1)[0], 0);
}

TEST(HostilePng, OneByOne) {
  PngSpec spec;
  spec.rows = {{10, 20, 30, 40}};
  const Image image = loadPng(writeFile(caseDir() / "one.png", makePng(spec)));
  ASSERT_EQ(image.width, 1);
  ASSERT_EQ(image.height, 1);
  EXPECT_EQ(pixelOf(image, 0, 0), (std::array<int, 4>{10, 20, 30, 40}));
}

TEST(HostilePng, EmptyFile) {
  const std::string path = writeFile(caseDir() / "empty.png", {});
  const std::string message = errorOf([&] { loadPng(path); });
  expectStartsWith(message, path + ": not a readable image");
  expectContains(message, {"the file is empty"});
}

TEST(HostilePng, TruncatedAnywhereBeforeTheImageDataEnds) {
  const fs::path dir = caseDir();
  const Bytes png = makePng(rgba4x2());
  // signature 8 + IHDR 25 + IDAT (12 + zlib 2 + 5 + 34 raw + 4) = 90 bytes before IEND.
  const std::size_t imageDataEnd = 8 + 25 + 12 + 2 + 5 + 34 + 4;
  ASSERT_EQ(png.size(), imageDataEnd + 12);
  for (std::size_t length : {std::size_t{1}, std::size_t{7}, std::size_t{8}, std::size_t{16}, std::size_t{33},
                             std::size_t{40}, std::size_t{60}, imageDataEnd - 5, imageDataEnd - 1}) {
    SCOPED_TRACE(length);
    const std::string path = writeFile(dir / ("cut" + std::to_string(length) + ".png"), Bytes(png.begin(), png.begin() + static_cast<std::ptrdiff_t>(length)));
    expectStartsWith(errorOf([&] { loadPng(path); }), path + ": ");
  }
}

TEST(HostilePng, HugeSizeInTheHeaderIsRefusedBeforeDecoding) {
  const fs::path dir = caseDir();
  for (std::uint32_t side : {std::uint32_t{16385}, std::uint32_t{100000}, std::uint32_t{0x7FFFFFFF}}) {
    PngSpec spec = rgba4x2();
    spec.width = side;  // the rows stay 4 pixels: only the header lies
    const std::string path = writeFile(dir / ("wide" + std::to_string(side) + ".png"), makePng(spec));
    const std::uint64_t decodedBefore = decodedImages();
    const std::string message = errorOf([&] { loadPng(path); });
    EXPECT_EQ(decodedImages(), decodedBefore) << "refused only after decoding";
    // stb refuses what exceeds its own 2^24 bound itself; ours is kMaxImageSide.
    expectStartsWith(message, path + ": ");
    if (side < (1u << 24)) {
      EXPECT_EQ(message, path + ": image is " + std::to_string(side) + "x2, expected each side in [1, 16384]");
    }
  }
  // A side of 0 is the same size limit, not "unknown image type" (issue 22, class 15).
  PngSpec zero = rgba4x2();
  zero.height = 0;
  const std::string path = writeFile(dir / "zero_height.png", makePng(zero));
  EXPECT_EQ(errorOf([&] { loadPng(path); }), path + ": image is 4x0, expected each side in [1, 16384]");
  // Huge on both sides (stb gave the reason of the last format it tried).
  PngSpec huge = rgba4x2();
  huge.width = huge.height = 100000;
  const std::string hugePath = writeFile(dir / "huge.png", makePng(huge));
  EXPECT_EQ(errorOf([&] { loadPng(hugePath); }), hugePath + ": image is 100000x100000, expected each side in [1, 16384]");
}

TEST(HostilePng, SixteenBitKeepsTheHighByte) {
  // stb_image reduces 16-bit samples to their high byte: 0x1234 -> 0x12.
  PngSpec spec;
  spec.width = 2;
  spec.bitDepth = 16;
  spec.rows = {{0x12, 0x34, 0xAB, 0xCD, 0xFF, 0xFF, 0x80, 0x00, 0x00, 0xFF, 0x7F, 0xFF, 0x01, 0x00, 0xFE, 0xFF}};
  const Image image = loadPng(writeFile(caseDir() / "rgba16.png", makePng(spec)));
  EXPECT_EQ(pixelOf(image, 0, 0), (std::array<int, 4>{0x12, 0xAB, 0xFF, 0x80}));
  EXPECT_EQ(pixelOf(image, 1, 0), (std::array<int, 4>{0x00, 0x7F, 0x01, 0xFE}));

  PngSpec grey;
  grey.width = 2;
  grey.bitDepth = 16;
  grey.colourType = kGrey;
  grey.rows = {{0xC0, 0x01, 0x05, 0xFF}};
  const Image greyImage = loadPng(writeFile(caseDir() / "grey16.png", makePng(grey)));
  EXPECT_EQ(pixelOf(greyImage, 0, 0), (std::array<int, 4>{0xC0, 0xC0, 0xC0, 255}));
  EXPECT_EQ(pixelOf(greyImage, 1, 0), (std::array<int, 4>{0x05, 0x05, 0x05, 255}));
}

TEST(HostilePng, GreyGreyAlphaAndRgbBecomeRgba) {
  const fs::path dir = caseDir();
  PngSpec grey;
  grey.width = 2;
  grey.colourType = kGrey;
  grey.rows = {{0x40, 0xC0}};
  const Image greyImage = loadPng(writeFile(dir / "grey.png", makePng(grey)));
  EXPECT_EQ(pixelOf(greyImage, 0, 0), (std::array<int, 4>{0x40, 0x40, 0x40, 255}));
  EXPECT_EQ(pixelOf(greyImage, 1, 0), (std::array<int, 4>{0xC0, 0xC0, 0xC0, 255}));

  // 1-bit grey: 0b10110000 -> white, black, white, white (samples scaled to 0 or 255).
  PngSpec bits;
  bits.width = 4;
  bits.colourType = kGrey;
  bits.bitDepth = 1;
  bits.rows = {{0xB0}};
  const Image bitImage = loadPng(writeFile(dir / "grey1.png", makePng(bits)));
  EXPECT_EQ(pixelOf(bitImage, 0, 0)[0], 255);
  EXPECT_EQ(pixelOf(bitImage, 1, 0)[0], 0);
  EXPECT_EQ(pixelOf(bitImage, 3, 0)[0], 255);

  PngSpec greyAlpha;
  greyAlpha.colourType = kGreyAlpha;
  greyAlpha.rows = {{0x30, 0x90}};
  const Image greyAlphaImage = loadPng(writeFile(dir / "grey_alpha.png", makePng(greyAlpha)));
  EXPECT_EQ(pixelOf(greyAlphaImage, 0, 0), (std::array<int, 4>{0x30, 0x30, 0x30, 0x90}));

  PngSpec rgb;
  rgb.colourType = kRgb;
  rgb.rows = {{1, 2, 3}};
  const Image rgbImage = loadPng(writeFile(dir / "rgb.png", makePng(rgb)));
  EXPECT_EQ(pixelOf(rgbImage, 0, 0), (std::array<int, 4>{1, 2, 3, 255}));
}

TEST(HostilePng, PaletteWithTransparency) {
  PngSpec spec;
  spec.width = 3;
  spec.colourType = kPalette;
  spec.palette = {10, 20, 30, 200, 150, 100, 7, 8, 9};
  spec.transparency = {255, 7};  // entry 2 has no tRNS value: opaque
  spec.rows = {{1, 0, 2}};
  const Image image = loadPng(writeFile(caseDir() / "palette.png", makePng(spec)));
  EXPECT_EQ(pixelOf(image, 0, 0), (std::array<int, 4>{200, 150, 100, 7}));
  EXPECT_EQ(pixelOf(image, 1, 0), (std::array<int, 4>{10, 20, 30, 255}));
  EXPECT_EQ(pixelOf(image, 2, 0), (std::array<int, 4>{7, 8, 9, 255}));
}

TEST(HostilePng, PaletteIndexPastThePaletteIsOpaqueBlackEveryTime) {
  // stb_image would read an uninitialised stack entry for index 200 of a 1-entry palette;
  // loadPng pads the palette, so the texel is defined (and the same on every run).
  PngSpec spec;
  spec.width = 2;
  spec.colourType = kPalette;
  spec.palette = {90, 80, 70};
  spec.rows = {{0, 200}};
  const std::string path = writeFile(caseDir() / "short_palette.png", makePng(spec));
  const Image image = loadPng(path);
  EXPECT_EQ(pixelOf(image, 0, 0), (std::array<int, 4>{90, 80, 70, 255}));
  EXPECT_EQ(pixelOf(image, 1, 0), (std::array<int, 4>{0, 0, 0, 255}));
}

TEST(HostilePng, CorruptImageData) {
  Bytes png = makePng(rgba4x2());
  png[8 + 25 + 8] = 0x00;  // the zlib header's first byte: compression method 0 is invalid
  const std::string path = writeFile(caseDir() / "bad_zlib.png", png);
  expectStartsWith(errorOf([&] { loadPng(path); }), path + ": cannot decode image");
}

// An empty IDAT chunk before the image data made Debian's stb_image memcpy to a null pointer
// (found by fuzzing under UBSan); empty IDATs are dropped, so the image is the same.
TEST(HostilePng, EmptyImageDataChunksChangeNothing) {
  const Bytes png = makePng(rgba4x2());
  constexpr std::size_t kFirstChunkAfterHeader = 8 + 25;  // signature, IHDR (12 + 13 bytes)
  Bytes emptyIdat;
  appendChunk(emptyIdat, "IDAT", {});
  Bytes padded(png.begin(), png.begin() + kFirstChunkAfterHeader);
  padded.insert(padded.end(), emptyIdat.begin(), emptyIdat.end());
  padded.insert(padded.end(), png.begin() + kFirstChunkAfterHeader, png.end());
  const fs::path dir = caseDir();
  const Image expected = loadPng(writeFile(dir / "plain.png", png));
  const Image image = loadPng(writeFile(dir / "empty_idat.png", padded));
  EXPECT_EQ(image.width, expected.width);
  EXPECT_EQ(image.height, expected.height);
  EXPECT_EQ(image.rgba, expected.rgba);
  // Only empty IDATs: no image data at all, refused by name.
  Bytes noData(png.begin(), png.begin() + kFirstChunkAfterHeader);
  noData.insert(noData.end(), emptyIdat.begin(), emptyIdat.end());
  appendChunk(noData, "IEND", {});
  const std::string path = writeFile(dir / "no_data.png", noData);
  expectStartsWith(errorOf([&] { loadPng(path); }), path + ": ");
}

TEST(HostilePng, OtherFormatsAreRefused) {
  const fs::path dir = caseDir();
  // Valid headers of formats stb_image decodes but loadPng does not accept.
  const std::vector<std::pair<std::string, std::string>> others{
      {"gif.png", "GIF89a\x01\x00\x01\x00\x00\x00\x00;"},
      {"pnm.png", "P6\n1 1\n255\nabc"},
      {"psd.png", "8BPS" + std::string(40, '\0')},
  };
  for (const auto& [name, bytes] : others) {
    const std::string path = writeText(dir / name, bytes);
    const std::string message = errorOf([&] { loadPng(path); });
    EXPECT_EQ(message, path + ": not a readable image (expected a PNG, JPEG, BMP, TGA, DDS or Radiance HDR file)");
  }
  // BMP is read now; a broken one says so.
  const std::string bmp = writeText(dir / "bmp.png", std::string("BM") + std::string(60, '\0'));
  expectStartsWith(errorOf([&] { loadPng(bmp); }), bmp + ": not a readable image (BMP: ");
}

// Debian 12's stb_image overruns its Huffman arrays on a DHT segment declaring more than 256
// codes (found by fuzzing): a valid JPEG loads, the same file with one count raised is refused
// before stb sees it, also through loadTexture (which reads the header first).
TEST(HostileJpeg, HuffmanTableWithTooManyCodesIsRefused) {
  const fs::path dir = caseDir();
  constexpr int kSide = 8;  // pixels
  std::vector<std::uint8_t> rgb(kSide * kSide * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<std::uint8_t>(i * 7);
  Bytes jpeg;
  const auto append = [](void* context, void* data, int size) {
    auto* out = static_cast<Bytes*>(context);
    const auto* bytes = static_cast<const std::uint8_t*>(data);
    out->insert(out->end(), bytes, bytes + size);
  };
  ASSERT_NE(stbi_write_jpg_to_func(append, &jpeg, kSide, kSide, 3, rgb.data(), 90), 0);
  const Image image = loadPng(writeFile(dir / "valid.jpg", jpeg));
  EXPECT_EQ(image.width, kSide);
  EXPECT_EQ(image.height, kSide);

  std::size_t dht = 0;
  for (std::size_t i = 2; i + 1 < jpeg.size(); ++i) {
    if (jpeg[i] == 0xFF && jpeg[i + 1] == 0xC4) {
      dht = i;
      break;
    }
  }
  ASSERT_NE(dht, 0u) << "stb wrote no DHT segment";
  // Marker (2 bytes), length (2), class and destination (1), then 16 counts: raise the last.
  Bytes corrupt = jpeg;
  corrupt[dht + 5 + 15] = 255;
  const std::string path = writeFile(dir / "corrupt.jpg", corrupt);
  expectContains(errorOf([&] { loadPng(path); }), {path + ": corrupt JPEG (a Huffman table with ", "(at most 256)"});
  expectStartsWith(errorOf([&] { loadTexture(path); }), path + ": ");
  // Cut off inside the counts: stb reads the missing bytes as 0 and still sums too many.
  const Bytes truncated{0xFF, 0xD8, 0xFF, 0xC4, 0xFF, 0x00, 0x00, 0x00, 0x0D, 0x89, 0x28, 0x08, 0x2F, 0x25};
  const std::string cut = writeFile(dir / "cut.jpg", truncated);
  expectContains(errorOf([&] { loadPng(cut); }), {cut + ": corrupt JPEG (a Huffman table with 282 codes"});
}

// Debian 12's stb_image loops forever on a run-length-encoded Radiance scanline holding a
// packet of length 0, and on one cut off by the end of the file (it reads zeros there), and
// leaves flat pixels past the end as its stack held them (found by fuzzing: a hang). The data
// is walked before stb sees it; a valid RLE file still decodes.
TEST(HostileHdr, ZeroLengthPacketsAndTruncatedDataAreRefused) {
  const fs::path dir = caseDir();
  const std::string header = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n";
  // One RLE scanline of 8 pixels: each channel a run of 8 (0x88) of one value.
  std::string rle = header + std::string("\x02\x02\x00\x08", 4);
  for (const char value : {'\x80', '\x40', '\x20', '\x81'}) rle += std::string("\x88", 1) + value;
  const ImageF image = loadHdrImage(writeText(dir / "valid.hdr", rle));
  ASSERT_EQ(image.width, 8);
  ASSERT_EQ(image.height, 1);
  for (int x = 0; x < 8; ++x) {
    EXPECT_FLOAT_EQ(image.rgba[static_cast<std::size_t>(x) * 4 + 0], 1.0f) << x;   // 128 * 2^(129-136)
    EXPECT_FLOAT_EQ(image.rgba[static_cast<std::size_t>(x) * 4 + 1], 0.5f) << x;
    EXPECT_FLOAT_EQ(image.rgba[static_cast<std::size_t>(x) * 4 + 3], 1.0f) << x;
  }

  const std::string zero = writeText(dir / "zero.hdr", header + std::string("\x02\x02\x00\x08\x00", 5));
  const std::string zeroMessage = errorOf([&] { loadHdrImage(zero); });
  expectContains(zeroMessage, {zero + ": corrupt Radiance HDR image (", "packet of length 0"});
  const std::string cut = writeText(dir / "cut.hdr", rle.substr(0, rle.size() - 3));
  expectContains(errorOf([&] { loadHdrImage(cut); }), {cut + ": corrupt Radiance HDR image (the file ends inside"});
  // Flat pixels (a width under 8 is never RLE): every byte must be there.
  const std::string flat = writeText(dir / "flat.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n" +
                                                           std::string(15, '\x80'));
  expectContains(errorOf([&] { loadHdrImage(flat); }), {flat + ": corrupt Radiance HDR image (the file ends inside"});
  // Never a material map.
  expectContains(errorOf([&] { loadTexture(zero); }), {zero + ": a Radiance HDR image holds floating-point texels"});
}

void appendLittleEndian(Bytes& out, std::uint32_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
}

// A TGA header (18 bytes): no ID, no colour map, `type` (2 true colour, 10 RLE), top-left origin.
Bytes tgaHeader(std::uint8_t type, int width, int height, std::uint8_t bits) {
  Bytes out{0, 0, type, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  appendLittleEndian(out, static_cast<std::uint32_t>(width), 2);
  appendLittleEndian(out, static_cast<std::uint32_t>(height), 2);
  out.push_back(bits);
  out.push_back(bits == 32 ? 0x28 : 0x20);  // top-left origin, alpha bits
  return out;
}

// Debian 12's stb_image copies a plain TGA's rows with a read that leaves its buffer as malloc
// left it when the file ends early: the texels of a truncated TGA were heap garbage, different
// from one load to the next (found by fuzzing: loadPng and loadTexture disagreed), and 18
// header bytes could declare 16384 x 16384 pixels (a timeout). Every TGA must hold its pixels.
TEST(HostileTga, TruncatedPixelDataIsRefused) {
  const fs::path dir = caseDir();
  Bytes plain = tgaHeader(2, 2, 2, 32);
  for (int i = 0; i < 4; ++i) plain.insert(plain.end(), {0x30, 0x20, 0x10, 0xFF});  // B, G, R, A
  const Image image = loadPng(writeFile(dir / "plain.tga", plain));
  ASSERT_EQ(image.width, 2);
  EXPECT_EQ(pixelOf(image, 1, 1), (std::array<int, 4>{0x10, 0x20, 0x30, 0xFF}));
  const std::string cut = writeFile(dir / "cut.tga", Bytes(plain.begin(), plain.end() - 1));
  expectContains(errorOf([&] { loadPng(cut); }), {cut + ": corrupt TGA (the file ends inside the pixel data (16 bytes"});
  expectStartsWith(errorOf([&] { loadTexture(cut); }), cut + ": corrupt TGA");
  const std::string huge = writeFile(dir / "huge.tga", tgaHeader(2, 16384, 16384, 8));
  const std::uint64_t decodedBefore = decodedImages();
  expectContains(errorOf([&] { loadTexture(huge); }), {huge + ": corrupt TGA (the file ends inside the pixel data"});
  EXPECT_EQ(decodedImages(), decodedBefore) << "refused only after decoding";

  // RLE: one packet repeating a pixel 4 times loads; without its pixel it is refused.
  Bytes rle = tgaHeader(10, 2, 2, 24);
  rle.insert(rle.end(), {0x83, 0x30, 0x20, 0x10});
  const Image rleImage = loadPng(writeFile(dir / "rle.tga", rle));
  EXPECT_EQ(pixelOf(rleImage, 0, 1), (std::array<int, 4>{0x10, 0x20, 0x30, 0xFF}));
  const std::string rleCut = writeFile(dir / "rle_cut.tga", Bytes(rle.begin(), rle.end() - 2));
  expectContains(errorOf([&] { loadPng(rleCut); }), {rleCut + ": corrupt TGA (the file ends inside the run-length"});
}

// TGA has no signature and stb_image tries its other decoders first: bytes starting 0xFF 0xD8
// that are not our 3-byte JPEG signature reached stb's JPEG decoder without the Huffman-table
// walk. Only a header stb's own TGA test accepts is taken for a TGA (found by review).
TEST(HostileTga, OnlyATgaHeaderReachesTheTgaDecoder) {
  const fs::path dir = caseDir();
  Bytes jpegLike{0xFF, 0xD8, 0x00, 0xFF, 0xC4, 0x00, 0x14, 0x00};
  jpegLike.resize(64, 0xFF);
  const std::string path = writeFile(dir / "soi.tga", jpegLike);
  expectContains(errorOf([&] { loadPng(path); }), {path + ": not a readable image (", "not a TGA header either"});
  int width = 0, height = 0;
  EXPECT_FALSE(readImageHeader(jpegLike.data(), jpegLike.size(), width, height));
}

// Debian 12's stb_image reads BMP rows byte by byte with zeros past the end: a 70-byte file could
// declare 16384 x 16384 pixels and have it decode 1 GiB from nothing. Every row must be there.
TEST(HostileBmp, TruncatedPixelDataIsRefused) {
  const fs::path dir = caseDir();
  const auto bmp = [](int width, int height, std::size_t rowBytes) {
    Bytes out{'B', 'M'};
    appendLittleEndian(out, static_cast<std::uint32_t>(54 + rowBytes * 2), 4);
    appendLittleEndian(out, 0, 4);
    appendLittleEndian(out, 54, 4);  // pixel data offset
    appendLittleEndian(out, 40, 4);  // BITMAPINFOHEADER
    appendLittleEndian(out, static_cast<std::uint32_t>(width), 4);
    appendLittleEndian(out, static_cast<std::uint32_t>(-height), 4);  // top-down
    appendLittleEndian(out, 1, 2);
    appendLittleEndian(out, 24, 2);
    for (int i = 0; i < 6; ++i) appendLittleEndian(out, 0, 4);
    for (int row = 0; row < 2; ++row) out.insert(out.end(), {0x30, 0x20, 0x10, 0x30, 0x20, 0x10, 0, 0});  // 2 BGR + pad
    return out;
  };
  const Bytes valid = bmp(2, 2, 8);
  const Image image = loadPng(writeFile(dir / "valid.bmp", valid));
  ASSERT_EQ(image.width, 2);
  EXPECT_EQ(pixelOf(image, 1, 1), (std::array<int, 4>{0x10, 0x20, 0x30, 0xFF}));
  const std::string cut = writeFile(dir / "cut.bmp", Bytes(valid.begin(), valid.end() - 3));
  expectContains(errorOf([&] { loadPng(cut); }), {cut + ": corrupt BMP (the file ends inside the pixel data (16 bytes"});
  const std::string huge = writeFile(dir / "huge.bmp", bmp(16384, 16384, 8));
  expectContains(errorOf([&] { loadTexture(huge); }), {huge + ": corrupt BMP (the file ends inside the pixel data"});
}

// stb_image 2.27 keeps a BMP palette on its stack and fills only the file's entries: an 8-bit
// index past a one-entry palette read stack garbage (found by review). The palette is padded
// with black, so the pixel is opaque black every time.
// Pixel data said to start inside the headers: stb 2.27 skipped a negative distance (zeros for
// pixels) or counted a negative palette and indexed its uninitialised stack (found by fuzzing:
// two loads of one 42-byte file differed). Refused, for every bit depth and both header kinds.
TEST(HostileBmp, PixelDataInsideTheHeadersIsRefused) {
  const fs::path dir = caseDir();
  const auto bmp = [](std::uint32_t headerBytes, int bits, std::uint32_t offset) {
    Bytes out{'B', 'M'};
    appendLittleEndian(out, 200, 4);
    appendLittleEndian(out, 0, 4);
    appendLittleEndian(out, offset, 4);
    appendLittleEndian(out, headerBytes, 4);
    if (headerBytes == 12) {  // OS/2: 16-bit sides, planes, bits
      appendLittleEndian(out, 2, 2);
      appendLittleEndian(out, 2, 2);
      appendLittleEndian(out, 1, 2);
      appendLittleEndian(out, static_cast<std::uint32_t>(bits), 2);
    } else {
      appendLittleEndian(out, 2, 4);
      appendLittleEndian(out, 2, 4);
      appendLittleEndian(out, 1, 2);
      appendLittleEndian(out, static_cast<std::uint32_t>(bits), 2);
      for (int i = 0; i < 6; ++i) appendLittleEndian(out, 0, 4);
    }
    out.resize(std::max<std::size_t>(200, offset + 16), 0x7F);
    return out;
  };
  int n = 0;
  for (const auto& [header, bits, offset] :
       {std::tuple{40u, 8, 0u}, std::tuple{40u, 8, 30u}, std::tuple{40u, 24, 0u}, std::tuple{40u, 24, 53u},
        std::tuple{12u, 8, 30u}, std::tuple{12u, 4, 37u}, std::tuple{12u, 24, 20u}}) {
    const std::string path = writeFile(dir / ("inside" + std::to_string(n++) + ".bmp"), bmp(header, bits, offset));
    expectContains(errorOf([&] { loadPng(path); }),
                   {path + ": corrupt BMP (the pixel data starts at byte " + std::to_string(offset) + ", inside the headers"});
  }
  // Right after the headers (24-bit) or a full palette (8-bit): read as before.
  EXPECT_EQ(loadPng(writeFile(dir / "after.bmp", bmp(40, 24, 54))).width, 2);
  EXPECT_EQ(loadPng(writeFile(dir / "palette.bmp", bmp(40, 8, 54 + 1024))).width, 2);
}

TEST(HostileBmp, PaletteIndexPastThePaletteIsOpaqueBlack) {
  const fs::path dir = caseDir();
  Bytes out{'B', 'M'};
  appendLittleEndian(out, 14 + 40 + 4 + 4, 4);
  appendLittleEndian(out, 0, 4);
  appendLittleEndian(out, 14 + 40 + 4, 4);  // pixel data after one palette entry
  appendLittleEndian(out, 40, 4);
  appendLittleEndian(out, 2, 4);   // width
  appendLittleEndian(out, 1, 4);   // height
  appendLittleEndian(out, 1, 2);
  appendLittleEndian(out, 8, 2);   // bits per pixel
  for (int i = 0; i < 6; ++i) appendLittleEndian(out, 0, 4);
  out.insert(out.end(), {0x30, 0x20, 0x10, 0x00});  // entry 0: B, G, R, reserved
  out.insert(out.end(), {0, 200, 0, 0});             // indices 0 and 200, padding
  const Image image = loadPng(writeFile(dir / "short_palette.bmp", out));
  ASSERT_EQ(image.width, 2);
  EXPECT_EQ(pixelOf(image, 0, 0), (std::array<int, 4>{0x10, 0x20, 0x30, 0xFF}));
  EXPECT_EQ(pixelOf(image, 1, 0), (std::array<int, 4>{0, 0, 0, 0xFF}));
}

// A DDS bit mask of all 32 bits shifted 1 by 32 (undefined behaviour) while being checked for one
// run of bits (found by review); it is one run, refused as more bits than are read.
TEST(HostileDds, FullThirtyTwoBitMaskIsRefusedCleanly) {
  const fs::path dir = caseDir();
  Bytes dds{'D', 'D', 'S', ' '};
  appendLittleEndian(dds, 124, 4);     // header size
  appendLittleEndian(dds, 0x100F, 4);  // caps, height, width, pitch, pixel format
  appendLittleEndian(dds, 1, 4);       // height
  appendLittleEndian(dds, 1, 4);       // width
  dds.resize(76, 0);  // the pixel format starts at byte 76 of the file
  appendLittleEndian(dds, 32, 4);          // pixel-format size
  appendLittleEndian(dds, 0x40, 4);        // RGB
  appendLittleEndian(dds, 0, 4);           // FourCC
  appendLittleEndian(dds, 32, 4);          // bits per texel
  appendLittleEndian(dds, 0xFFFFFFFFu, 4);  // red mask
  appendLittleEndian(dds, 0xFF00, 4);
  appendLittleEndian(dds, 0xFF0000, 4);
  appendLittleEndian(dds, 0, 4);
  dds.resize(128, 0);  // caps: none
  dds.insert(dds.end(), {0x10, 0x20, 0x30, 0x40});
  const std::string path = writeFile(dir / "mask.dds", dds);
  expectContains(errorOf([&] { loadPng(path); }), {path + ": DDS: the red channel has 32 bits (at most 16 read)"});
}

TEST(HostilePng, SpecialFilesAreRefused) {
  const fs::path dir = caseDir();
  expectStartsWith(errorOf([&] { loadPng(dir.string()); }), dir.string() + ": cannot open image file (it is a directory)");
  if (fs::exists("/dev/zero")) {
    EXPECT_EQ(errorOf([&] { loadPng("/dev/zero"); }), "/dev/zero: cannot open image file (not a regular file)");
  }
  EXPECT_EQ(errorOf([&] { loadPng((dir / "missing.png").string()); }), (dir / "missing.png").string() + ": image file not found");
  // A path the system cannot look up is not "not found": the reason is named (issue 22, class 15).
  std::error_code ec;
  fs::remove(dir / "loop_a", ec);
  fs::remove(dir / "loop_b", ec);
  fs::create_symlink(dir / "loop_b", dir / "loop_a");
  fs::create_symlink(dir / "loop_a", dir / "loop_b");
  expectContains(errorOf([&] { loadPng((dir / "loop_a").string()); }), {"cannot open image file (", "symbolic links"});
  const std::string tooLong = (dir / (std::string(300, 'a') + ".png")).string();
  expectContains(errorOf([&] { loadPng(tooLong); }), {"cannot open image file (", "too long"});
}

// A truncated PNG says so in words, not stb's code "outofdata" (issue 22, class 15).
TEST(HostilePng, TruncatedImageDataIsNamedInWords) {
  const fs::path dir = caseDir();
  const Bytes png = makePng(rgba4x2());
  const std::string path = writeFile(dir / "cut.png", Bytes(png.begin(), png.begin() + 60));
  expectContains(errorOf([&] { loadPng(path); }), {path + ": ", "truncated"});
}

TEST(HostilePng, TextureBudgetRefusesBeforeDecoding) {
  const fs::path dir = caseDir();
  const std::string small = writeFile(dir / "small.png", makePng(rgba4x2()));
  PngSpec big = rgba4x2();
  big.width = 4096;  // the header says 4096 x 2 = 32 KiB of texels; the data is still 4 x 2
  const std::string liar = writeFile(dir / "liar.png", makePng(big));
  // liar.png with its chain: 32768 + 32768 / 3 = 43690 bytes.
  std::uintmax_t budget = 44 + 43690 - 1;  // room for small.png and one byte short of liar.png
  const Texture texture = loadTexture(small, budget);
  EXPECT_EQ(budget, std::uintmax_t{43690 - 1}) << "the 4x2 texture uses 32 bytes, its 2x1 and 1x1 levels 12";
  const std::string message = errorOf([&] { loadTexture(liar, budget); });
  expectStartsWith(message, liar + ": image is 4096x2 (43690 bytes of texels with its mip chain), more than the 43689 "
                                   "bytes left");
  EXPECT_EQ(budget, std::uintmax_t{43690 - 1}) << "a refused texture uses nothing";
}

// ---- scene files ----

TEST(HostileScene, SpecialFilesAndSize) {
  const fs::path dir = caseDir();
  if (fs::exists("/dev/zero")) {
    EXPECT_EQ(errorOf([] { loadSceneFile("/dev/zero"); }), "/dev/zero: cannot open scene file (not a regular file)");
  }
  const std::string empty = writeText(dir / "empty.json", "");
  expectStartsWith(errorOf([&] { loadSceneFile(empty); }), empty + ": line 1, column 1:");
  // A sparse file one byte over the limit: refused from its size, without reading it.
  const fs::path huge = dir / "huge.json";
  writeText(huge, "{");
  fs::resize_file(huge, kMaxSceneFileBytes + 1);
  EXPECT_EQ(errorOf([&] { loadSceneFile(huge.string()); }),
            huge.string() + ": scene file is 33554433 bytes (32.0 MiB), larger than the limit of 32 MiB for a scene file");
  // The same limit for text handed over in memory.
  const std::string text(kMaxSceneFileBytes + 1, ' ');
  expectStartsWith(errorOf([&] { parseScene(text, "big.json", "."); }), "big.json: scene file is 33554433 bytes (32.0 MiB), larger than");
}

TEST(HostileScene, BinaryAndWrongEncodings) {
  const fs::path dir = caseDir();
  const std::string png = writeFile(dir / "image.json", makePng(rgba4x2()));
  expectContains(errorOf([&] { loadSceneFile(png); }), {png + ": line 1, column 1:", "invalid JSON"});
  // UTF-16 (with a byte-order mark) is not JSON text.
  const std::string utf16 = writeFile(dir / "utf16.json", {0xFF, 0xFE, '{', 0, '}', 0});
  expectContains(errorOf([&] { loadSceneFile(utf16); }), {utf16 + ": line 1, column 1:", "invalid JSON"});
  const std::string nul = writeText(dir / "nul.json", std::string("{\"nodes\": [\0]}", 14));
  expectContains(errorOf([&] { loadSceneFile(nul); }), {nul + ": line 1, column 12:", "invalid JSON"});
}

TEST(HostileScene, NestingDepthIsBounded) {
  // kMaxJsonDepth levels in all: the top-level object plus kMaxJsonDepth - 1 arrays pass
  // the parser (and the reader then refuses the content); one more level does not.
  const auto nested = [](int arrays) {
    return R"({"nodes": [], "ambient": )" + std::string(static_cast<std::size_t>(arrays), '[') +
           std::string(static_cast<std::size_t>(arrays), ']') + "}";
  };
  expectStartsWith(errorOf([&] { parseScene(nested(kMaxJsonDepth - 1), "deep.json", "."); }),
                   "deep.json: ambient: expected an array of 3 numbers");
  const std::string message = errorOf([&] { parseScene(nested(kMaxJsonDepth), "deep.json", "."); });
  expectStartsWith(message, "deep.json: ambient[0][0]");
  expectContains(message, {"JSON nests deeper than " + std::to_string(kMaxJsonDepth) + " levels"});
  // Far deeper: the same message, without exhausting the stack or memory: the document stops
  // at the limit, having built one array per level (the ambient key's value and its arrays).
  const std::uint64_t builtBefore = jsonValuesBuilt();
  expectContains(errorOf([&] { parseScene(nested(10'000'000), "deeper.json", "."); }), {"JSON nests deeper than"});
  EXPECT_LE(jsonValuesBuilt() - builtBefore, static_cast<std::uint64_t>(kMaxJsonDepth) + 2);
}

// Long flat lists (issue 22, class 10): nlohmann's parse callback and its ordered objects made
// a million nodes or materials quadratic (over 120 s). The document is built in linear time;
// the order of keys and the duplicate-key check are kept.
TEST(HostileScene, LongFlatListsParseInLinearTime) {
  constexpr std::size_t kCount = 300'000;
  std::string nodes = R"({"nodes": [)", materials = R"({"nodes": [], "materials": {)";
  for (std::size_t i = 0; i < kCount; ++i) {
    nodes += i ? ",{}" : "{}";
    materials += (i ? ",\"m" : "\"m") + std::to_string(i) + "\": {}";
  }
  // Each value is built once: the root, the list and its kCount entries (no copy, no re-walk).
  const std::uint64_t builtBefore = jsonValuesBuilt();
  EXPECT_EQ(parseScene(nodes + "]}", "nodes.json", ".").nodes.size(), kCount);
  EXPECT_EQ(jsonValuesBuilt() - builtBefore, kCount + 2);
  const Scene scene = parseScene(materials + "}}", "materials.json", ".");
  ASSERT_EQ(scene.materials.size(), kCount);
  EXPECT_EQ(scene.materials.front().name, "m0");
  EXPECT_EQ(scene.materials.back().name, "m" + std::to_string(kCount - 1));
  expectStartsWith(errorOf([&] { parseScene(materials + R"(, "m5": {}}})", "dup.json", "."); }),
                   "dup.json: materials.m5: duplicate key");
  // Quadratic, these took minutes (nlohmann's own parse searched every key read so far before
  // adding one): ctest's time limit fails such a regression; the count above says the builder,
  // which appends without searching, built the document.
}

// More nodes or materials than any scene needs: refused with the limit, before they are read.
TEST(HostileScene, NodeAndMaterialCountsAreBounded) {
  std::string roots = R"({"nodes": [{})", children = R"({"nodes": [{"children": [{})";
  std::string materials = R"({"nodes": [], "materials": {"m0": {})";
  for (std::size_t i = 1; i <= kMaxSceneNodes; ++i) {
    roots += ",{}";
    if (i < kMaxSceneNodes) children += ",{}";
  }
  for (std::size_t i = 1; i <= kMaxSceneMaterials; ++i) materials += ",\"m" + std::to_string(i) + "\": {}";
  const std::string limit = std::to_string(kMaxSceneNodes);
  EXPECT_EQ(errorOf([&] { parseScene(roots + "]}", "roots.json", "."); }),
            "roots.json: nodes: " + std::to_string(kMaxSceneNodes + 1) + " nodes, at most " + limit +
                " are allowed (counting children)");
  expectStartsWith(errorOf([&] { parseScene(children + "]}]}", "children.json", "."); }),
                   "children.json: nodes[0].children[" + std::to_string(kMaxSceneNodes - 1) + "]: more than " + limit +
                       " nodes");
  EXPECT_EQ(errorOf([&] { parseScene(materials + "}}", "materials.json", "."); }),
            "materials.json: materials: " + std::to_string(kMaxSceneMaterials + 1) + " materials, at most " +
                std::to_string(kMaxSceneMaterials) + " are allowed");
}

TEST(HostileScene, ColoursAreBounded) {
  const std::string limit = std::to_string(static_cast<int>(kMaxColourValue));
  EXPECT_NO_THROW(parseScene(R"({"nodes": [], "ambient": [0, 10000, 0]})", "c.json", "."));
  EXPECT_EQ(errorOf([] { parseScene(R"({"nodes": [], "ambient": [0, 10000.5, 0]})", "c.json", "."); }),
            "c.json: ambient[1]: expected a number in [0, " + limit + "], got 10000.5");
  expectStartsWith(errorOf([] { parseScene(R"({"nodes": [], "lights": [{"diffuse": [1e38, 1, 1]}]})", "c.json", "."); }),
                   "c.json: lights[0].diffuse[0]: expected a number in [0, " + limit + "]");
  expectStartsWith(errorOf([] { parseScene(R"({"nodes": [], "materials": {"m": {"ks": [1, 1, 3e38]}}})", "c.json", "."); }),
                   "c.json: materials.m.ks[2]: expected a number in [0, " + limit + "]");
}

TEST(HostileScene, HundredMillionTrianglesAreRefusedUpFront) {
  // Three spheres of 4096 x 4096 segments ask for 3 x 33,546,240 triangles; the first one is
  // refused from its parameters alone, before a single vertex is built.
  std::string nodes;
  for (int i = 0; i < 3; ++i) {
    nodes += std::string(i ? ", " : "") + R"({"name": "s)" + std::to_string(i) +
             R"(", "mesh": {"type": "sphere", "stacks": 4096, "slices": 4096}})";
  }
  const std::uint64_t meshesBefore = meshesBuilt();
  const std::string message = errorOf([&] { parseScene(R"({"nodes": [)" + nodes + "]}", "many.json", "."); });
  EXPECT_EQ(meshesBuilt(), meshesBefore) << "refused only after building";
  EXPECT_EQ(message, "many.json: nodes[0].mesh: this mesh brings the scene to 33546240 triangles; at most 20000000 are "
                     "allowed");
  expectStartsWith(errorOf([] { parseScene(R"({"nodes": [{"mesh": {"type": "torus", "rings": 4096, "sides": 4096}}]})",
                                           "torus.json", "."); }),
                   "torus.json: nodes[0].mesh: this mesh brings the scene to 33554432 triangles");
}

TEST(HostileScene, BadTexturesNameSceneKeyAndFile) {
  const fs::path dir = caseDir();
  writeFile(dir / "empty.png", {});
  writeText(dir / "scene.json", R"({"materials": {"m": {"normal_map": "empty.png"}}, "nodes": []})");
  const std::string message = errorOf([&] { loadSceneFile((dir / "scene.json").string()); });
  expectStartsWith(message, (dir / "scene.json").string() + ": materials.m.normal_map: " + (dir / "empty.png").string() +
                                ": not a readable image");
}

TEST(HostileScene, TextureMemoryIsBoundedPerScene) {
  // A first map takes 44 bytes (32 and its chain) of the 1 GiB; a second one whose header
  // claims 16384^2 (1 GiB, 1365 MiB with its chain) does not fit and is refused before decoding.
  const fs::path dir = caseDir();
  writeFile(dir / "small.png", makePng(rgba4x2()));
  PngSpec huge = rgba4x2();
  huge.width = 16384;
  huge.height = 16384;
  writeFile(dir / "huge.png", makePng(huge));
  const std::string scene = writeText(
      dir / "scene.json",
      R"({"materials": {"a": {"diffuse_map": "small.png"}, "b": {"diffuse_map": "huge.png"}}, "nodes": []})");
  const std::uint64_t decodedBefore = decodedImages();
  const std::string message = errorOf([&] { loadSceneFile(scene); });
  EXPECT_LE(decodedImages() - decodedBefore, 1u) << "the huge map was decoded before it was refused";
  expectStartsWith(message, scene + ": materials.b.diffuse_map: " + (dir / "huge.png").string() +
                                ": image is 16384x16384 (1431655765 bytes (1365.3 MiB) of texels with its mip chain), "
                                "more than the 1073741780 bytes (1024.0 MiB) left of the scene's texture memory limit of "
                                "1024 MiB");
  // The same map twice is one texture: it counts once.
  writeText(dir / "twice.json", R"({"materials": {"a": {"diffuse_map": "small.png", "normal_map": "small.png"}}, "nodes": []})");
  const Scene twice = loadSceneFile((dir / "twice.json").string());
  EXPECT_EQ(twice.materials[0].diffuseMap, twice.materials[0].normalMap);
}

TEST(HostileScene, HeightfieldsAreBoundedAndNameTheirKeys) {
  const fs::path dir = caseDir();
  writeFile(dir / "small.png", makePng(rgba4x2()));
  writeFile(dir / "empty.png", {});
  const auto load = [&](const std::string& mesh) {
    const std::string scene = writeText(dir / "scene.json", R"({"nodes": [{"mesh": )" + mesh + "}]}");
    return errorOf([&] { loadSceneFile(scene); });
  };
  const std::string scene = (dir / "scene.json").string();
  // A height map that is no image names the mesh's key and the file.
  expectStartsWith(load(R"({"type": "heightfield", "height_map": "empty.png"})"),
                   scene + ": nodes[0].mesh.height_map: " + (dir / "empty.png").string() + ": not a readable image");
  // Segment counts past any integer type, negative, or not integers.
  for (const char* resolution : {"[18446744073709551615, 1]", "[-1, 1]", "[1e30, 1]", "[1, null]", "{\"x\": 1}"}) {
    expectStartsWith(load(std::string(R"({"type": "heightfield", "height_map": "small.png", "resolution": )") + resolution + "}"),
                     scene + ": nodes[0].mesh.resolution");
  }
  // A grid of 1000 x 1000 quads (2 million triangles), then one of 4096 x 2200 (18,022,400):
  // the second is refused from its keys, before its 9 million vertices are built.
  const std::string first = R"({"mesh": {"type": "heightfield", "height_map": "small.png", "resolution": [1000, 1000]}})";
  const std::string second = R"({"mesh": {"type": "heightfield", "height_map": "small.png", "resolution": [4096, 2200]}})";
  const std::string two = writeText(dir / "two.json", R"({"nodes": [)" + first + ", " + second + "]}");
  const std::string message = errorOf([&] { loadSceneFile(two); });
  EXPECT_EQ(message, two + ": nodes[1].mesh: this mesh brings the scene to 20022400 triangles; at most 20000000 are allowed");
}

// ---- OBJ files ----

const char* const kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

TEST(HostileObj, SpecialFilesAndSize) {
  const fs::path dir = caseDir();
  if (fs::exists("/dev/zero")) {
    EXPECT_EQ(errorOf([] { loadObj("/dev/zero"); }), "/dev/zero: cannot open OBJ file (not a regular file)");
  }
  expectStartsWith(errorOf([&] { loadObj(dir.string()); }), dir.string() + ": cannot open OBJ file (it is a directory)");
  const fs::path huge = dir / "huge.obj";
  writeText(huge, "v");
  fs::resize_file(huge, kMaxObjFileBytes + 1);
  expectStartsWith(errorOf([&] { loadObj(huge.string()); }), huge.string() + ": OBJ file is 268435457 bytes (256.0 MiB), larger than the limit of 256 MiB");
  // An MTL named by mtllib is held to its own limit.
  writeText(dir / "m.obj", std::string("mtllib big.mtl\nusemtl a\n") + kTriangleObj);
  writeText(dir / "big.mtl", "newmtl a\n");
  fs::resize_file(dir / "big.mtl", kMaxMtlFileBytes + 1);
  expectStartsWith(errorOf([&] { loadObj((dir / "m.obj").string()); }),
                   (dir / "m.obj").string() + ": mtllib: " + (dir / "big.mtl").string() + ": MTL file is 16777217 bytes");
}

// Faces with many corners (issue 22, class 11): tinyobjloader's ear clipping is quadratic in a
// face's corners (one face of 400,000 corners took over 120 s). A face may have 16,384, and the
// faces above 64 corners 65,536 in all; past either, refused with the line, before parsing.
TEST(HostileObj, FacesWithManyCornersAreBounded) {
  const fs::path dir = caseDir();
  // `faces` convex polygons of `corners` corners each, one after the other.
  const auto polygons = [&](const std::string& name, int faces, int corners) {
    std::ostringstream text;  // a stream: GCC 12 for aarch64 warns (-Wrestrict) on " " + std::string
    for (int f = 0; f < faces; ++f) {
      for (int i = 0; i < corners; ++i) {
        const double a = 6.283185307179586 * i / corners;
        text << "v " << std::cos(a) << ' ' << std::sin(a) << ' ' << f << '\n';
      }
      text << 'f';
      for (int i = 0; i < corners; ++i) text << ' ' << f * corners + i + 1;
      text << '\n';
    }
    writeText(dir / name, text.str());
    return (dir / name).string();
  };
  const std::string fine = polygons("fine.obj", 2, 2000);
  EXPECT_EQ(loadObj(fine).meshes.at(0).triangleCount(), 2u * 1998u);
  const std::string huge = polygons("huge.obj", 1, 16385);
  EXPECT_EQ(errorOf([&] { loadObj(huge); }),
            huge + ":16386: a face of 16385 corners; at most 16384 are read (tinyobjloader's triangulation takes time "
                   "quadratic in them)");
  const std::string many = polygons("many.obj", 33, 2048);  // the 33rd face passes 65,536 corners
  expectStartsWith(errorOf([&] { loadObj(many); }),
                   many + ":" + std::to_string(33 * 2049) + ": faces of more than 64 corners hold more than 65536");
  EXPECT_NO_THROW(loadObj(polygons("small.obj", 2000, 60)));  // small faces do not count
}

TEST(HostileObj, TriangleBudgetIsCheckedBeforeParsing) {
  const fs::path dir = caseDir();
  // Line 8 is a convex hexagon: 4 triangles, bringing the file to 1 + 4 = 5.
  const std::string path =
      writeText(dir / "six.obj", "v 0 0 0\nv 1 0 0\nv 2 1 0\nf 1 2 3\nv 1 2 0\nv 0 2 0\nv -1 1 0\nf 1 2 3 4 5 6\n");
  EXPECT_EQ(loadObj(path, ObjLimits{5, kMaxSceneTextureBytes}).meshes[0].triangleCount(), 5u);
  EXPECT_EQ(errorOf([&] { loadObj(path, ObjLimits{4, kMaxSceneTextureBytes}); }),
            path + ":8: the file has more than 4 triangles, the most this scene can take");
}

// Positions of the single mesh, in index order.
std::vector<vec3> cornerPositions(const ObjModel& model) {
  std::vector<vec3> corners;
  for (const Mesh& mesh : model.meshes) {
    for (std::uint32_t index : mesh.indices) corners.push_back(mesh.vertices[index].posModel);
  }
  return corners;
}

TEST(HostileObj, Utf16AndLineEndsDecodeToTheSameModel) {
  const fs::path dir = caseDir();
  const std::string text = "# utf\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const std::vector<vec3> expected{vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)};
  const auto utf16 = [&](bool bigEndian, bool byteOrderMark) {
    Bytes bytes;
    if (byteOrderMark) bytes = bigEndian ? Bytes{0xFE, 0xFF} : Bytes{0xFF, 0xFE};
    for (char c : text) {
      if (bigEndian) bytes.push_back(0);
      bytes.push_back(static_cast<std::uint8_t>(c));
      if (!bigEndian) bytes.push_back(0);
    }
    return bytes;
  };
  std::string crOnly = text;
  std::replace(crOnly.begin(), crOnly.end(), '\n', '\r');
  std::string crLf;
  for (char c : text) crLf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const std::vector<std::pair<std::string, Bytes>> variants{
      {"utf16be_bom.obj", utf16(true, true)},   {"utf16le_bom.obj", utf16(false, true)},
      {"utf16be.obj", utf16(true, false)},      {"utf16le.obj", utf16(false, false)},
      {"utf8_bom.obj", [&] { Bytes b{0xEF, 0xBB, 0xBF}; b.insert(b.end(), text.begin(), text.end()); return b; }()},
      {"cr.obj", Bytes(crOnly.begin(), crOnly.end())},
      {"crlf.obj", Bytes(crLf.begin(), crLf.end())},
  };
  for (const auto& [name, bytes] : variants) {
    SCOPED_TRACE(name);
    EXPECT_EQ(cornerPositions(loadObj(writeFile(dir / name, bytes))), expected);
  }
  const std::string utf32 = writeFile(dir / "utf32.obj", {0xFF, 0xFE, 0, 0, 'v', 0, 0, 0});
  EXPECT_EQ(errorOf([&] { loadObj(utf32); }), utf32 + ": the file is UTF-32 encoded; expected UTF-8 or UTF-16 text");
}

TEST(HostileObj, MaterialNamesWithSpaces) {
  const fs::path dir = caseDir();
  writeText(dir / "spaces.mtl", "newmtl  Hard Shiny\tPlastic \nKd 0.25 0.5 0.75\n");
  const std::string path =
      writeText(dir / "spaces.obj", std::string("mtllib spaces.mtl\nusemtl Hard   Shiny Plastic\n") + kTriangleObj);
  const ObjModel model = loadObj(path);
  ASSERT_EQ(model.materials.size(), 1u);
  ASSERT_TRUE(model.hasMaterial[0]);
  EXPECT_EQ(model.materials[0].name, "Hard Shiny Plastic");
  EXPECT_EQ(model.materials[0].kd, vec3(0.25f, 0.5f, 0.75f));
  // A name that differs in a word is still unknown, with its line.
  const std::string wrong =
      writeText(dir / "wrong.obj", std::string("mtllib spaces.mtl\n") + kTriangleObj + "usemtl Hard Plastic\nf 1 2 3\n");
  EXPECT_EQ(errorOf([&] { loadObj(wrong); }), wrong + ":6: usemtl: material 'Hard Plastic' is not in the MTL file(s)");
}

TEST(HostileObj, WindowsTexturePathsAndOutOfRangeColours) {
  const fs::path dir = caseDir();
  fs::create_directories(dir / "maps");
  writeFile(dir / "maps" / "albedo.png", makePng(rgba4x2()));
  writeText(dir / "win.mtl", "newmtl m\nmap_Kd maps\\albedo.png\n");
  const ObjModel model = loadObj(writeText(dir / "win.obj", std::string("mtllib win.mtl\nusemtl m\n") + kTriangleObj));
  ASSERT_TRUE(model.materials[0].diffuseMap);
  EXPECT_EQ(model.materials[0].diffuseMap->width, 4);

  writeText(dir / "bright.mtl", "newmtl m\nKd 1 20000 1\n");
  const std::string bright = writeText(dir / "bright.obj", std::string("mtllib bright.mtl\nusemtl m\n") + kTriangleObj);
  EXPECT_EQ(errorOf([&] { loadObj(bright); }), bright + ": material 'm' Kd must be in [0, 10000], got 20000.000000");
}

}  // namespace
}  // namespace twr

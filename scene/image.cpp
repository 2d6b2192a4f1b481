#include "scene/image.h"

#include "scene/block_compression.h"
#include "scene/dds.h"
#include "scene/errors.h"
#include "scene/read_file.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace twr {

namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr unsigned char kJpegSignature[3] = {0xFF, 0xD8, 0xFF};

bool startsWith(const std::uint8_t* bytes, std::size_t size, const unsigned char* signature, std::size_t length) {
  return size >= length && std::memcmp(bytes, signature, length) == 0;
}

std::string stbReason() {
  const char* reason = stbi_failure_reason();
  return reason ? reason : "unknown";
}

constexpr unsigned char kBmpSignature[2] = {'B', 'M'};
constexpr unsigned char kHdrSignatureRadiance[11] = {'#', '?', 'R', 'A', 'D', 'I', 'A', 'N', 'C', 'E', '\n'};
constexpr unsigned char kHdrSignatureRgbe[7] = {'#', '?', 'R', 'G', 'B', 'E', '\n'};
// Formats stb_image also reads but nobody here needs (their decoders have had their share of
// memory-safety bugs): recognised only to be refused by name.
constexpr unsigned char kGifSignature[4] = {'G', 'I', 'F', '8'};
constexpr unsigned char kPsdSignature[4] = {'8', 'B', 'P', 'S'};
constexpr unsigned char kPicSignature[4] = {0x53, 0x80, 0xF6, 0x34};

// What the first bytes say. TGA has no signature: a file none of the others claims is
// tried as TGA (stb's TGA test checks the header's fields), and refused when that fails.
ImageFileFormat formatOfBytes(const std::uint8_t* bytes, std::size_t size) {
  if (startsWith(bytes, size, kPngSignature, sizeof kPngSignature)) return ImageFileFormat::Png;
  if (startsWith(bytes, size, kJpegSignature, sizeof kJpegSignature)) return ImageFileFormat::Jpeg;
  if (isDds(bytes, size)) return ImageFileFormat::Dds;
  if (startsWith(bytes, size, kHdrSignatureRadiance, sizeof kHdrSignatureRadiance) ||
      startsWith(bytes, size, kHdrSignatureRgbe, sizeof kHdrSignatureRgbe)) {
    return ImageFileFormat::Hdr;
  }
  if (startsWith(bytes, size, kBmpSignature, sizeof kBmpSignature)) return ImageFileFormat::Bmp;
  if (startsWith(bytes, size, kGifSignature, sizeof kGifSignature) ||
      startsWith(bytes, size, kPsdSignature, sizeof kPsdSignature) ||
      startsWith(bytes, size, kPicSignature, sizeof kPicSignature) ||
      (size >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7')) {
    return ImageFileFormat::Unknown;
  }
  return size > 0 ? ImageFileFormat::Tga : ImageFileFormat::Unknown;
}

constexpr const char* kReadableFormats = "PNG, JPEG, BMP, TGA, DDS or Radiance HDR";

// JPEG markers (ITU T.81, table B.1) this walk needs.
constexpr std::uint8_t kJpegMarkerDht = 0xC4;  // define Huffman tables
constexpr std::uint8_t kJpegMarkerSos = 0xDA;  // start of scan: entropy-coded data follows
constexpr std::uint8_t kJpegMarkerEoi = 0xD9;
// Huffman codes a table may define (ITU T.81, B.2.4.2: at most 256 symbols).
constexpr std::size_t kJpegMaxHuffmanSymbols = 256;
// A DHT table: one byte of class and destination, 16 code-length counts (bytes).
constexpr std::size_t kJpegHuffmanHeaderBytes = 17;

bool standaloneJpegMarker(std::uint8_t marker) {
  return marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7);  // SOI, TEM, RSTn
}

// Debian 12's stb_image builds each Huffman table into fixed arrays of 256 symbols without
// checking that the 16 counts add up to at most 256, so a corrupt DHT segment writes past
// them (found by fuzzing, UBSan at stb_image.h:1990). This walks the segments (and the
// entropy-coded data after each SOS, up to the next marker) and returns "" when every table
// it finds is within the limit, else what is wrong. Anything else malformed is left to stb.
std::string jpegHuffmanProblem(const std::uint8_t* bytes, std::size_t size) {
  std::size_t at = 2;  // after SOI
  while (at < size) {
    if (bytes[at] != 0xFF) {  // junk where a marker belongs: stb refuses or skips it; so do we
      ++at;
      continue;
    }
    while (at < size && bytes[at] == 0xFF) ++at;  // fill bytes
    if (at >= size) return "";
    const std::uint8_t marker = bytes[at++];
    if (marker == kJpegMarkerEoi) return "";
    if (standaloneJpegMarker(marker)) continue;
    if (at + 2 > size) return "";  // truncated: stb reports it
    const std::size_t length = (std::size_t{bytes[at]} << 8) | bytes[at + 1];
    if (length < 2) return "";  // stb refuses a segment shorter than its own length field
    const std::size_t end = std::min(size, at + length);
    if (marker == kJpegMarkerDht) {
      // Tables as far as the segment's length says, as stb reads them: a byte past the end of
      // a truncated file reads as 0 (found by fuzzing: counts cut off mid-table).
      const auto byteAt = [&](std::size_t i) -> std::size_t { return i < size ? bytes[i] : 0; };
      for (std::size_t table = at + 2; table < at + length;) {
        std::size_t symbols = 0;
        for (std::size_t i = 1; i < kJpegHuffmanHeaderBytes; ++i) symbols += byteAt(table + i);
        if (symbols > kJpegMaxHuffmanSymbols) {
          return "a Huffman table with " + std::to_string(symbols) + " codes (at most " +
                 std::to_string(kJpegMaxHuffmanSymbols) + ")";
        }
        table += kJpegHuffmanHeaderBytes + symbols;
      }
    }
    at = end;
    if (marker == kJpegMarkerSos) {
      // Entropy-coded data: 0xFF 0x00 is a stuffed byte and 0xFF 0xD0..0xD7 a restart marker;
      // any other 0xFF pair starts the next segment.
      while (at + 1 < size && !(bytes[at] == 0xFF && bytes[at + 1] != 0x00 && !(bytes[at + 1] >= 0xD0 && bytes[at + 1] <= 0xD7))) {
        ++at;
      }
      if (at + 1 >= size) return "";
    }
  }
  return "";
}

// PNG chunk framing: 4-byte length, 4-byte type, data, 4-byte CRC (bytes).
constexpr std::size_t kPngChunkOverhead = 12;
// A palette holds at most 256 RGB entries (bytes).
constexpr std::uint32_t kFullPaletteBytes = 256 * 3;

std::uint32_t readBigEndian32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

void appendBigEndian32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

// CRC-32 as PNG defines it (polynomial 0xEDB88320, reflected).
std::uint32_t pngCrc(const std::uint8_t* data, std::size_t size) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

// stb_image keeps a 256-entry palette on the stack and fills only the entries PLTE gives, so
// a pixel index beyond them would read whatever the stack held and the texels would change
// from run to run. Returns a copy of the PNG with PLTE padded to 256 entries (the new ones
// opaque black), or an empty vector when the file needs no change.
std::vector<std::uint8_t> withFullPalette(const std::uint8_t* bytes, std::size_t size) {
  std::size_t at = sizeof kPngSignature;
  while (size - at >= kPngChunkOverhead) {
    const std::uint32_t length = readBigEndian32(bytes + at);
    if (length > size - at - kPngChunkOverhead) break;  // malformed: stb reports it
    const std::uint8_t* type = bytes + at + 4;
    if (std::memcmp(type, "IDAT", 4) == 0) break;  // PLTE must come before the image data
    if (std::memcmp(type, "PLTE", 4) == 0) {
      if (length % 3 != 0 || length >= kFullPaletteBytes) break;
      std::vector<std::uint8_t> out(bytes, bytes + at);
      appendBigEndian32(out, kFullPaletteBytes);
      const std::size_t chunkStart = out.size();
      out.insert(out.end(), type, type + 4 + length);
      out.resize(chunkStart + 4 + kFullPaletteBytes, 0);
      appendBigEndian32(out, pngCrc(out.data() + chunkStart, 4 + kFullPaletteBytes));
      out.insert(out.end(), bytes + at + kPngChunkOverhead + length, bytes + size);
      return out;
    }
    at += kPngChunkOverhead + length;
  }
  return {};
}

// stb_image copies each IDAT chunk's data into a buffer it allocates on the first non-empty
// one: an empty first IDAT makes it memcpy 0 bytes to a null pointer (undefined behaviour,
// found by fuzzing under UBSan). Empty IDAT chunks carry nothing, so they are dropped: returns
// a copy without them, or an empty vector when there are none.
std::vector<std::uint8_t> withoutEmptyImageData(const std::uint8_t* bytes, std::size_t size) {
  std::vector<std::uint8_t> out;
  std::size_t copiedUpTo = 0;
  std::size_t at = sizeof kPngSignature;
  while (size - at >= kPngChunkOverhead) {
    const std::uint32_t length = readBigEndian32(bytes + at);
    if (length > size - at - kPngChunkOverhead) break;  // malformed: stb reports it
    if (length == 0 && std::memcmp(bytes + at + 4, "IDAT", 4) == 0) {
      out.insert(out.end(), bytes + copiedUpTo, bytes + at);
      copiedUpTo = at + kPngChunkOverhead;
    }
    at += kPngChunkOverhead + length;
  }
  if (copiedUpTo == 0) return {};
  out.insert(out.end(), bytes + copiedUpTo, bytes + size);
  return out;
}

}  // namespace

Image makeImage(int width, int height, std::uint32_t fillRgba) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i + 0] = static_cast<std::uint8_t>(fillRgba >> 24);
    image.rgba[i + 1] = static_cast<std::uint8_t>(fillRgba >> 16);
    image.rgba[i + 2] = static_cast<std::uint8_t>(fillRgba >> 8);
    image.rgba[i + 3] = static_cast<std::uint8_t>(fillRgba);
  }
  return image;
}

bool readImageHeader(const std::uint8_t* bytes, std::size_t size, int& width, int& height) {
  const ImageFileFormat format = formatOfBytes(bytes, size);
  if (format == ImageFileFormat::Unknown || size > static_cast<std::size_t>(INT_MAX)) return false;
  if (format == ImageFileFormat::Dds) return readDdsHeader(bytes, size, width, height);
  // stb reads a JPEG's Huffman tables while looking for its size, so they are checked first.
  if (format == ImageFileFormat::Jpeg && !jpegHuffmanProblem(bytes, size).empty()) return false;
  int channels = 0;
  return stbi_info_from_memory(bytes, static_cast<int>(size), &width, &height, &channels) != 0;
}

ImageFileFormat imageFileFormat(const std::uint8_t* bytes, std::size_t size) { return formatOfBytes(bytes, size); }

std::string_view toString(ImageFileFormat format) {
  switch (format) {
    case ImageFileFormat::Png: return "PNG";
    case ImageFileFormat::Jpeg: return "JPEG";
    case ImageFileFormat::Bmp: return "BMP";
    case ImageFileFormat::Tga: return "TGA";
    case ImageFileFormat::Hdr: return "Radiance HDR";
    case ImageFileFormat::Dds: return "DDS";
    case ImageFileFormat::Unknown: break;
  }
  return "unknown";
}

namespace {

// The checks every stb-decoded format shares: the header first, so a huge declared size is
// refused before any allocation. Returns the size stb will decode.
void checkStbHeader(const std::uint8_t* bytes, int length, ImageFileFormat format, const std::string& name, int& width,
                    int& height) {
  int channels = 0;
  if (!stbi_info_from_memory(bytes, length, &width, &height, &channels)) {
    if (format == ImageFileFormat::Tga) {
      throw InputError(name + ": not a readable image (no PNG, JPEG, BMP, DDS or HDR signature, and not a TGA "
                              "header either; expected a " + std::string(kReadableFormats) + " file)");
    }
    throw InputError(name + ": not a readable image (" + std::string(toString(format)) + ": " + stbReason() + ")");
  }
  if (width <= 0 || height <= 0 || width > kMaxImageSide || height > kMaxImageSide) {
    throw InputError(name + ": image is " + std::to_string(width) + "x" + std::to_string(height) +
                     ", expected each side in [1, " + std::to_string(kMaxImageSide) + "]");
  }
}

Image decodeDdsLevel0(const std::uint8_t* bytes, std::size_t size, const std::string& name) {
  const DdsFile file = parseDds(bytes, size, name);
  const DdsLevel& level = file.levels.front();
  Image image = makeImage(level.width, level.height);
  image.rgba = file.blockFormat ? decodeBlockLevel(*file.blockFormat, level.width, level.height, level.data.data())
                                : level.data;
  return image;
}

}  // namespace

Image decodeImage(const std::uint8_t* bytes, std::size_t size, const std::string& nameForMessages) {
  const ImageFileFormat format = formatOfBytes(bytes, size);
  if (format == ImageFileFormat::Unknown) {
    throw InputError(nameForMessages + ": not a readable image (expected a " + std::string(kReadableFormats) + " file" +
                     (size == 0 ? std::string(", the file is empty)") : std::string(")")));
  }
  if (format == ImageFileFormat::Hdr) {
    throw InputError(nameForMessages + ": a Radiance HDR image holds floating-point texels, for environment maps; "
                                       "a material map takes an 8-bit image (PNG, JPEG, BMP, TGA or DDS)");
  }
  if (format == ImageFileFormat::Dds) return decodeDdsLevel0(bytes, size, nameForMessages);
  const bool png = format == ImageFileFormat::Png;
  const std::vector<std::uint8_t> padded = png ? withFullPalette(bytes, size) : std::vector<std::uint8_t>{};
  if (!padded.empty()) {
    bytes = padded.data();
    size = padded.size();
  }
  const std::vector<std::uint8_t> compacted = png ? withoutEmptyImageData(bytes, size) : std::vector<std::uint8_t>{};
  if (!compacted.empty()) {
    bytes = compacted.data();
    size = compacted.size();
  }
  if (size > static_cast<std::size_t>(INT_MAX)) {
    throw InputError(nameForMessages + ": image data larger than " + describeBytes(INT_MAX));
  }
  if (format == ImageFileFormat::Jpeg) {
    const std::string problem = jpegHuffmanProblem(bytes, size);
    if (!problem.empty()) throw InputError(nameForMessages + ": corrupt JPEG (" + problem + ")");
  }
  const int length = static_cast<int>(size);
  int width = 0, height = 0, channels = 0;
  checkStbHeader(bytes, length, format, nameForMessages, width, height);
  int decodedWidth = 0, decodedHeight = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load_from_memory(bytes, length, &decodedWidth, &decodedHeight, &channels, 4), stbi_image_free);
  if (!data) {
    throw InputError(nameForMessages + ": cannot decode image (" + std::string(toString(format)) + ": " + stbReason() +
                     ")");
  }
  // The decoder reads the header again; it must agree with what was checked above.
  if (decodedWidth != width || decodedHeight != height) {
    throw InputError(nameForMessages + ": cannot decode image (header and data disagree on the size)");
  }
  Image image = makeImage(width, height);
  std::memcpy(image.rgba.data(), data.get(), image.rgba.size());
  return image;
}

ImageF decodeHdrImage(const std::uint8_t* bytes, std::size_t size, const std::string& nameForMessages) {
  if (formatOfBytes(bytes, size) != ImageFileFormat::Hdr) {
    throw InputError(nameForMessages + ": not a Radiance HDR image (no '#?RADIANCE' or '#?RGBE' line at the start)");
  }
  if (size > static_cast<std::size_t>(INT_MAX)) {
    throw InputError(nameForMessages + ": image data larger than " + describeBytes(INT_MAX));
  }
  const int length = static_cast<int>(size);
  int width = 0, height = 0, channels = 0;
  checkStbHeader(bytes, length, ImageFileFormat::Hdr, nameForMessages, width, height);
  int decodedWidth = 0, decodedHeight = 0;
  std::unique_ptr<float, void (*)(void*)> data(
      stbi_loadf_from_memory(bytes, length, &decodedWidth, &decodedHeight, &channels, 4), stbi_image_free);
  if (!data) throw InputError(nameForMessages + ": cannot decode the Radiance HDR image (" + stbReason() + ")");
  if (decodedWidth != width || decodedHeight != height) {
    throw InputError(nameForMessages + ": cannot decode image (header and data disagree on the size)");
  }
  ImageF image;
  image.width = width;
  image.height = height;
  image.rgba.assign(data.get(), data.get() + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  return image;
}

ImageF loadHdrImage(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": image file not found");
  const std::string bytes = readFileCapped(path, kMaxImageFileBytes, "image file");
  return decodeHdrImage(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), path);
}

Image loadPng(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path + ": image file not found");
  const std::string bytes = readFileCapped(path, kMaxImageFileBytes, "image file");
  return decodeImage(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), path);
}

void savePng(const std::string& path, const Image& image) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);
  if (image.width <= 0 || image.height <= 0 ||
      !stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(), image.width * 4)) {
    throw InputError(path + ": cannot write PNG");
  }
}

}  // namespace twr

#include "scene/image.h"

#include "scene/work_counters.h"

#include "scene/block_compression.h"
#include "scene/dds.h"
#include "scene/errors.h"
#include "scene/read_file.h"

#include <stb_image.h>
#include <stb_image_write.h>

// stb_image_write's zlib compressor: public (STBIWDEF) and exported by Debian's libstb, but
// declared only inside the header's implementation part.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len, int quality);

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace twr {

namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
// The IHDR chunk follows the signature: length (4 bytes), "IHDR", width, height (big-endian).
constexpr int kPngWidthAt = 16;
constexpr int kPngSizeEnd = 24;
constexpr unsigned char kJpegSignature[3] = {0xFF, 0xD8, 0xFF};

bool startsWith(const std::uint8_t* bytes, std::size_t size, const unsigned char* signature, std::size_t length) {
  return size >= length && std::memcmp(bytes, signature, length) == 0;
}

// stb's failure reason, in words where its short codes would puzzle a user.
std::string stbReason() {
  const char* reason = stbi_failure_reason();
  if (!reason) return "unknown";
  const std::string code = reason;
  if (code == "outofdata") return "the file ends before its image data does: truncated";
  if (code == "unknown image type") return "not a format stb_image reads, or a corrupt header";
  return code;
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
// a copy without them, or an empty vector when there are none. stb reads a chunk whose CRC is
// cut off by the end of the file (the missing bytes read as 0), so an empty IDAT needs only
// its length and type to count (found by fuzzing: a file ending 4 bytes into one).
std::vector<std::uint8_t> withoutEmptyImageData(const std::uint8_t* bytes, std::size_t size) {
  constexpr std::size_t kLengthAndType = 8;  // bytes
  std::vector<std::uint8_t> out;
  std::size_t copiedUpTo = 0;
  std::size_t at = sizeof kPngSignature;
  while (size - at >= kLengthAndType) {
    const std::uint32_t length = readBigEndian32(bytes + at);
    if (length == 0 && std::memcmp(bytes + at + 4, "IDAT", 4) == 0) {
      out.insert(out.end(), bytes + copiedUpTo, bytes + at);
      copiedUpTo = std::min(size, at + kPngChunkOverhead);
    }
    if (size - at < kPngChunkOverhead || length > size - at - kPngChunkOverhead) break;  // malformed: stb reports it
    at += kPngChunkOverhead + length;
  }
  if (copiedUpTo == 0) return {};
  out.insert(out.end(), bytes + copiedUpTo, bytes + size);
  return out;
}

// Radiance HDR, as Debian 12's stb_image 2.27 reads it. Its header lines are tokens up to a
// newline (at most 1023 bytes; a NUL ends a token early, as stb compares them as C strings).
constexpr std::size_t kHdrTokenBytes = 1023;
// Scanlines of a width in [8, 32768) may be run-length encoded: 2, 2, then the width in two
// bytes (high first, its top bit clear), then each of the 4 RGBE channels as packets: a count
// byte over 128 repeats the next byte count - 128 times, else count bytes follow.
constexpr int kHdrRleMinWidth = 8, kHdrRleMaxWidth = 32768;  // [inclusive, exclusive)
constexpr std::uint8_t kHdrRleRunBase = 128;
constexpr int kHdrChannels = 4;  // R, G, B, shared exponent (bytes per pixel)

// Debian 12's stb_image decodes Radiance pixel data without checking where the file ends: a
// zero-length packet (or the zeros it reads past the end of a truncated file) never moves its
// loop forward, so it spins forever (found by fuzzing), and flat pixels past the end are left
// as whatever its stack held. This walks the data after the header exactly as stb will and
// returns "" when stb can decode it to the end (or refuses it by itself), else what is wrong.
// width and height are the header's, already checked.
std::string hdrDataProblem(const std::uint8_t* bytes, std::size_t size, int width, int height) {
  std::size_t at = 0;
  const auto get8 = [&]() -> std::uint8_t { return at < size ? bytes[at++] : 0; };
  const auto token = [&]() {
    std::string text;
    std::uint8_t c = get8();
    while (at < size && c != '\n') {
      text.push_back(static_cast<char>(c));
      if (text.size() == kHdrTokenBytes) {
        while (at < size && get8() != '\n') {
        }
        break;
      }
      c = get8();
    }
    return text;
  };
  (void)token();  // "#?RADIANCE" or "#?RGBE"
  for (;;) {
    const std::string line = token();
    if (line.empty() || line[0] == '\0') break;
  }
  (void)token();  // "-Y height +X width"
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  const std::size_t flatBytes = pixels * kHdrChannels;
  const auto flatProblem = [&](std::size_t from) -> std::string {
    if (size - std::min(size, from) >= flatBytes) return "";
    return "the file ends inside the pixel data (" + std::to_string(width) + "x" + std::to_string(height) +
           " pixels of 4 bytes from byte " + std::to_string(from) + ", " + std::to_string(size - std::min(size, from)) +
           " bytes left)";
  };
  if (width < kHdrRleMinWidth || width >= kHdrRleMaxWidth) return flatProblem(at);
  for (int row = 0; row < height; ++row) {
    const std::size_t rowStart = at;
    if (size - at < 4) return "the file ends at scanline " + std::to_string(row) + " of " + std::to_string(height);
    const std::uint8_t c1 = get8(), c2 = get8(), high = get8();
    // Not run-length encoded: stb reads the rest of the image (from its first pixel) flat.
    if (c1 != 2 || c2 != 2 || (high & 0x80)) return flatProblem(rowStart);
    const int length = (high << 8) | get8();
    if (length != width) return "";  // stb refuses it
    for (int channel = 0; channel < kHdrChannels; ++channel) {
      for (int x = 0; x < width;) {
        if (at >= size) {
          return "the file ends inside scanline " + std::to_string(row) + " (stb_image would read zeros forever)";
        }
        const int count = get8();
        if (count > kHdrRleRunBase) {
          if (at >= size) return "the file ends inside scanline " + std::to_string(row);
          (void)get8();
          if (count - kHdrRleRunBase > width - x) return "";  // stb refuses it
          x += count - kHdrRleRunBase;
        } else {
          if (count == 0) {
            return "scanline " + std::to_string(row) + " holds a packet of length 0 (stb_image would read it forever)";
          }
          if (count > width - x) return "";  // stb refuses it
          if (size - at < static_cast<std::size_t>(count)) return "the file ends inside scanline " + std::to_string(row);
          at += static_cast<std::size_t>(count);
          x += count;
        }
      }
    }
  }
  return "";
}

std::uint32_t readLittleEndian16(const std::uint8_t* bytes, std::size_t size, std::size_t at) {
  const auto byte = [&](std::size_t i) -> std::uint32_t { return i < size ? bytes[i] : 0; };  // stb reads 0 past the end
  return byte(at) | (byte(at + 1) << 8);
}
std::uint32_t readLittleEndian32(const std::uint8_t* bytes, std::size_t size, std::size_t at) {
  return readLittleEndian16(bytes, size, at) | (readLittleEndian16(bytes, size, at + 2) << 16);
}

std::string endsInsidePixels(std::size_t needed, std::size_t from, std::size_t size) {
  return "the file ends inside the pixel data (" + std::to_string(needed) + " bytes from byte " + std::to_string(from) +
         ", " + std::to_string(size - std::min(size, from)) + " left)";
}

// TGA (Truevision TGA 2.0) header: ID length, colour-map type, image type, colour-map start,
// length and entry bits, origin, width, height, bits per pixel, descriptor (bytes).
constexpr std::size_t kTgaHeaderBytes = 18;
constexpr std::uint8_t kTgaRleFlag = 8;      // image types 9, 10, 11
constexpr std::uint8_t kTgaRepeatFlag = 0x80, kTgaCountMask = 0x7F;  // RLE packet header

// stb_image's test for a TGA header (colour-map type 0 or 1, an image type it reads, a
// size, bits it reads), repeated here so that a file is called TGA only when stb's TGA decoder
// is the one that reads it: stb tries its other decoders first, and bytes 0xFF 0xD8 that we
// do not call JPEG would reach its JPEG decoder past the Huffman-table walk.
bool looksLikeTga(const std::uint8_t* bytes, std::size_t size) {
  const auto byte = [&](std::size_t i) -> std::uint8_t { return i < size ? bytes[i] : 0; };
  const std::uint8_t mapType = byte(1), type = byte(2);
  const auto bitsOk = [](std::uint8_t bits) { return bits == 8 || bits == 15 || bits == 16 || bits == 24 || bits == 32; };
  if (mapType > 1) return false;
  if (mapType == 1) {
    if (type != 1 && type != 9) return false;
    if (!bitsOk(byte(7))) return false;
  } else if (type != 2 && type != 3 && type != 10 && type != 11) {
    return false;
  }
  if (readLittleEndian16(bytes, size, 12) < 1 || readLittleEndian16(bytes, size, 14) < 1) return false;
  const std::uint8_t bits = byte(16);
  if (mapType == 1 && bits != 8 && bits != 16) return false;
  return bitsOk(bits);
}

// Debian 12's stb_image reads a plain (not RLE, not colour-mapped) TGA's rows with a copy that
// leaves the rest of its buffer as malloc left it when the file ends early, so texels of a
// truncated file are whatever the heap held, different from run to run (found by fuzzing:
// two loads of one file disagreed); and a few header bytes can declare a 16384 x 16384 image
// that it then decodes from nothing. Every TGA must hold its palette and all of its pixels:
// returns "" when it does (or stb refuses the header by itself), else what is missing.
std::string tgaDataProblem(const std::uint8_t* bytes, std::size_t size) {
  const auto byte = [&](std::size_t i) -> std::uint8_t { return i < size ? bytes[i] : 0; };
  const bool mapped = byte(1) != 0, rle = (byte(2) & kTgaRleFlag) != 0;
  const std::size_t mapStart = readLittleEndian16(bytes, size, 3), mapLength = readLittleEndian16(bytes, size, 5);
  const std::uint8_t mapBits = byte(7), bits = byte(16);
  const std::size_t width = readLittleEndian16(bytes, size, 12), height = readLittleEndian16(bytes, size, 14);
  // Bytes per stored pixel (or palette entry), as stb's tga_get_comp decides.
  const auto bytesOf = [&](std::uint8_t b) -> std::size_t {
    switch (b) {
      case 8: return 1;
      case 15: return 2;
      case 16: return 2;
      case 24: return 3;
      case 32: return 4;
      default: return 0;
    }
  };
  std::size_t at = kTgaHeaderBytes + byte(0);  // after the image ID
  if (mapped) {
    if (bytesOf(mapBits) == 0 || mapLength == 0) return "";  // stb refuses it
    at += mapStart + mapLength * bytesOf(mapBits);
    if (at > size) return "the file ends inside the colour map";
  }
  const std::size_t pixelBytes = bytesOf(bits);
  if (pixelBytes == 0) return "";  // stb refuses it
  const std::size_t pixels = width * height;
  if (!rle) return size - std::min(size, at) >= pixels * pixelBytes ? "" : endsInsidePixels(pixels * pixelBytes, at, size);
  for (std::size_t done = 0; done < pixels;) {
    if (at >= size) return "the file ends inside the run-length-encoded pixels (" + std::to_string(done) + " of " +
                           std::to_string(pixels) + " read)";
    const std::uint8_t packet = bytes[at++];
    const std::size_t count = std::min<std::size_t>(1 + (packet & kTgaCountMask), pixels - done);
    const std::size_t stored = (packet & kTgaRepeatFlag) ? pixelBytes : count * pixelBytes;
    if (size - at < stored) return "the file ends inside the run-length-encoded pixels";
    at += stored;
    done += count;
  }
  return "";
}

// BMP: Debian 12's stb_image reads rows byte by byte and takes zeros past the end, so a 60-byte
// file can declare 16384 x 16384 pixels and have stb allocate and fill 1 GiB from nothing.
// Every row must be in the file (stb reads BMP only uncompressed or with bit fields; each row
// padded to 4 bytes). width and height are the header's, already checked.
constexpr std::size_t kBmpOffsetPixelData = 10, kBmpOffsetHeaderSize = 14;
constexpr std::uint32_t kBmpCoreHeaderBytes = 12;  // OS/2 BITMAPCOREHEADER: 16-bit sides
constexpr std::size_t kBmpFileHeaderBytes = 14;
// stb counts an OS/2 file's 3-byte palette entries from here (bytes; 14 + 24, as it reads them).
constexpr std::size_t kBmpCorePaletteFrom = 38;
std::string bmpDataProblem(const std::uint8_t* bytes, std::size_t size, int width, int height) {
  const std::uint32_t headerSize = readLittleEndian32(bytes, size, kBmpOffsetHeaderSize);
  const std::size_t bitsAt = headerSize == kBmpCoreHeaderBytes ? 24 : 28;
  const std::size_t bits = readLittleEndian16(bytes, size, bitsAt);
  const std::size_t rowBytes = (static_cast<std::size_t>(width) * bits + 31) / 32 * 4;
  const std::size_t needed = rowBytes * static_cast<std::size_t>(height);
  const std::size_t from = readLittleEndian32(bytes, size, kBmpOffsetPixelData);
  // Pixel data that starts inside the headers: stb skips a negative distance to the end of the
  // file (zeros for pixels) and, for 1-, 4- and 8-bit files, counts a negative palette, reads
  // none of it and indexes its uninitialised stack array (found by fuzzing: a file with offset 0
  // loaded differently twice).
  const bool core = headerSize == kBmpCoreHeaderBytes;
  const std::size_t headersEnd = kBmpFileHeaderBytes + headerSize;
  const std::size_t paletteFrom = core ? kBmpCorePaletteFrom : headersEnd;  // where stb counts entries from
  if (from < headersEnd || (bits <= 8 && from < paletteFrom)) {
    return "the pixel data starts at byte " + std::to_string(from) + ", inside the headers (they end at byte " +
           std::to_string(std::max(headersEnd, bits <= 8 ? paletteFrom : headersEnd)) + ")";
  }
  return size - std::min(size, from) >= needed ? "" : endsInsidePixels(needed, from, size);
}

// stb_image 2.27 keeps a BMP's palette in a 256-entry array on its stack and fills only the
// entries the file gives, so a 1-, 4- or 8-bit pixel index past a short palette read whatever
// the stack held (found by review; the PNG twin above was found by fuzzing). Returns a copy
// with the palette padded to 2^bits entries (black; stb makes every entry opaque) and the
// pixel data offset moved past them, or an empty vector when the file needs no change.
// Call after bmpDataProblem: the offset is then inside the file.
std::vector<std::uint8_t> withFullBmpPalette(const std::uint8_t* bytes, std::size_t size) {
  const std::uint32_t headerSize = readLittleEndian32(bytes, size, kBmpOffsetHeaderSize);
  const bool core = headerSize == kBmpCoreHeaderBytes;
  const std::uint32_t bits = readLittleEndian16(bytes, size, core ? 24 : 28);
  if (bits != 1 && bits != 4 && bits != 8) return {};
  const std::int64_t offset = readLittleEndian32(bytes, size, kBmpOffsetPixelData);
  // Entries stb reads, as it counts them: OS/2 core headers 3 bytes each (counted from byte 38),
  // the others 4 bytes each after the header.
  constexpr std::int64_t kFileHeaderBytes = 14, kCoreCountFrom = 38;
  const std::int64_t entryBytes = core ? 3 : 4;
  const std::int64_t entries = core ? (offset - kCoreCountFrom) / 3 : (offset - kFileHeaderBytes - headerSize) / 4;
  const std::int64_t full = std::int64_t{1} << bits;
  if (entries < 1 || entries >= full) return {};  // stb refuses an empty palette; a full one needs nothing
  const std::size_t insertAt = static_cast<std::size_t>(kFileHeaderBytes + headerSize + entries * entryBytes);
  if (insertAt > size || static_cast<std::size_t>(offset) > size) return {};
  const std::size_t added = static_cast<std::size_t>((full - entries) * entryBytes);
  std::vector<std::uint8_t> out(bytes, bytes + insertAt);
  out.insert(out.end(), added, 0);
  out.insert(out.end(), bytes + insertAt, bytes + size);
  const std::uint32_t moved = static_cast<std::uint32_t>(offset) + static_cast<std::uint32_t>(added);
  for (std::size_t i = 0; i < 4; ++i) out[kBmpOffsetPixelData + i] = static_cast<std::uint8_t>(moved >> (8 * i));
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

namespace {
// A BMP's height is negative when its rows are stored top first; stb_image 2.27's info call
// returns it as stored while its loader decodes abs(height) rows, so a top-down BMP was refused
// as "2x-2" (found writing the regression tests). INT_MIN has no absolute value: it stays out
// of range and is refused with the size.
int bmpRows(int height) { return height < 0 && height != INT_MIN ? -height : height; }
}  // namespace

bool readImageHeader(const std::uint8_t* bytes, std::size_t size, int& width, int& height) {
  const ImageFileFormat format = formatOfBytes(bytes, size);
  if (format == ImageFileFormat::Unknown || size > static_cast<std::size_t>(INT_MAX)) return false;
  if (format == ImageFileFormat::Dds) return readDdsHeader(bytes, size, width, height);
  // stb reads a JPEG's Huffman tables while looking for its size, so they are checked first.
  if (format == ImageFileFormat::Jpeg && !jpegHuffmanProblem(bytes, size).empty()) return false;
  if (format == ImageFileFormat::Tga && !looksLikeTga(bytes, size)) return false;
  int channels = 0;
  if (!stbi_info_from_memory(bytes, static_cast<int>(size), &width, &height, &channels)) return false;
  if (format == ImageFileFormat::Bmp) height = bmpRows(height);
  return true;
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
  // A PNG's size sits at a fixed place in its first chunk: checked here, because stb's header
  // reader refuses 0 or huge sizes with the reason of the last format it tried.
  if (format == ImageFileFormat::Png && length >= kPngSizeEnd) {
    const auto bigEndian = [&](int at) {
      return (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
             (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
    };
    const std::uint32_t declaredWidth = bigEndian(kPngWidthAt), declaredHeight = bigEndian(kPngWidthAt + 4);
    if (declaredWidth == 0 || declaredHeight == 0 || declaredWidth > static_cast<std::uint32_t>(kMaxImageSide) ||
        declaredHeight > static_cast<std::uint32_t>(kMaxImageSide)) {
      throw InputError(name + ": image is " + std::to_string(declaredWidth) + "x" + std::to_string(declaredHeight) +
                       ", expected each side in [1, " + std::to_string(kMaxImageSide) + "]");
    }
  }
  int channels = 0;
  if ((format == ImageFileFormat::Tga && !looksLikeTga(bytes, static_cast<std::size_t>(length))) ||
      !stbi_info_from_memory(bytes, length, &width, &height, &channels)) {
    if (format == ImageFileFormat::Tga) {
      throw InputError(name + ": not a readable image (no PNG, JPEG, BMP, DDS or HDR signature, and not a TGA "
                              "header either; expected a " + std::string(kReadableFormats) + " file)");
    }
    throw InputError(name + ": not a readable image (" + std::string(toString(format)) + ": " + stbReason() + ")");
  }
  if (format == ImageFileFormat::Bmp) height = bmpRows(height);
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

std::string renderSizeProblem(int width, int height) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  if (width < 1 || width > kMaxImageSide || height < 1 || height > kMaxImageSide) {
    return "image size " + size + " must be within 1.." + std::to_string(kMaxImageSide) + " on each side";
  }
  if (static_cast<long long>(width) * height > kMaxRenderPixels) {
    return "image size " + size + " is " + std::to_string(static_cast<long long>(width) * height) +
           " pixels, at most " + std::to_string(kMaxRenderPixels) + " (8192x8192, or 16384x4096) are drawn";
  }
  return {};
}

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
  const std::string problem = format == ImageFileFormat::Tga   ? tgaDataProblem(bytes, size)
                              : format == ImageFileFormat::Bmp ? bmpDataProblem(bytes, size, width, height)
                                                               : std::string();
  if (!problem.empty()) throw InputError(nameForMessages + ": corrupt " + std::string(toString(format)) + " (" + problem + ")");
  const std::vector<std::uint8_t> bmpPadded =
      format == ImageFileFormat::Bmp ? withFullBmpPalette(bytes, size) : std::vector<std::uint8_t>{};
  if (bmpPadded.size() > static_cast<std::size_t>(INT_MAX)) {
    throw InputError(nameForMessages + ": image data larger than " + describeBytes(INT_MAX));
  }
  const std::uint8_t* decodeBytes = bmpPadded.empty() ? bytes : bmpPadded.data();
  const int decodeLength = bmpPadded.empty() ? length : static_cast<int>(bmpPadded.size());
  int decodedWidth = 0, decodedHeight = 0;
  workCounters().imagesDecoded.fetch_add(1, std::memory_order_relaxed);
  std::unique_ptr<stbi_uc, void (*)(void*)> data(
      stbi_load_from_memory(decodeBytes, decodeLength, &decodedWidth, &decodedHeight, &channels, 4), stbi_image_free);
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
  const std::string problem = hdrDataProblem(bytes, size, width, height);
  if (!problem.empty()) throw InputError(nameForMessages + ": corrupt Radiance HDR image (" + problem + ")");
  int decodedWidth = 0, decodedHeight = 0;
  workCounters().imagesDecoded.fetch_add(1, std::memory_order_relaxed);
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
  // Not there at all; a path that cannot be looked up (a symlink loop, a name too long) is
  // left to readFileCapped, which says why.
  if (!std::filesystem::exists(path, ec) && !ec) throw InputError(path + ": image file not found");
  const std::string bytes = readFileCapped(path, kMaxImageFileBytes, "image file");
  return decodeHdrImage(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), path);
}

Image loadPng(const std::string& path) {
  std::error_code ec;
  // Not there at all; a path that cannot be looked up (a symlink loop, a name too long) is
  // left to readFileCapped, which says why.
  if (!std::filesystem::exists(path, ec) && !ec) throw InputError(path + ": image file not found");
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

std::vector<std::uint8_t> zlibCompress(const std::uint8_t* data, std::size_t size) {
  if (size > static_cast<std::size_t>(INT_MAX)) throw std::length_error("zlibCompress: over 2 GiB");
  // Level 8, stb's default for PNGs: the mid-point of its speed against size.
  constexpr int kCompressionLevel = 8;
  int length = 0;
  unsigned char* packed = stbi_zlib_compress(const_cast<unsigned char*>(data), static_cast<int>(size), &length,
                                             kCompressionLevel);
  if (!packed) throw std::bad_alloc();
  std::vector<std::uint8_t> out(packed, packed + length);
  std::free(packed);  // Debian's libstb allocates with malloc (STBIW_MALLOC's default)
  return out;
}

}  // namespace twr

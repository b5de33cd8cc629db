#include "libshapeproc/render/png_text.hpp"

#include <array>
#include <cstdint>

#include "libshapeproc/core/check.hpp"

namespace shapeproc::render {

namespace {

constexpr char kSignature[] = "\x89PNG\r\n\x1a\n";
constexpr std::size_t kSignatureSize = 8, kIhdrEnd = kSignatureSize + 4 + 4 + 13 + 4;

// CRC-32 of the PNG specification (polynomial 0xEDB88320, reflected).
std::uint32_t crc32(const std::string& bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char byte : bytes) c = table[(c ^ byte) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void put_u32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((v >> shift) & 0xFF);
}

std::uint32_t get_u32(const std::string& in, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v = (v << 8) | static_cast<unsigned char>(in[at + k]);
  return v;
}

bool is_png(const std::string& png) {
  return png.size() >= kIhdrEnd &&
         png.compare(0, kSignatureSize, kSignature, kSignatureSize) == 0 &&
         png.compare(kSignatureSize + 4, 4, "IHDR") == 0;
}

}  // namespace

std::string add_png_text(const std::string& png, const PngText& text) {
  core::check(is_png(png), "add_png_text", "the bytes are not a PNG starting with IHDR");
  std::string chunks;
  for (const auto& [keyword, value] : text) {
    core::check(!keyword.empty() && keyword.size() < 80 && keyword.find('\0') == std::string::npos,
                "add_png_text", "a keyword has 1-79 characters, got '" + keyword + "'");
    std::string body = "tEXt" + keyword;
    body += '\0';
    for (char c : value) body += c == '\0' ? ' ' : c;
    put_u32(chunks, static_cast<std::uint32_t>(body.size() - 4));
    chunks += body;
    put_u32(chunks, crc32(body));
  }
  return png.substr(0, kIhdrEnd) + chunks + png.substr(kIhdrEnd);
}

PngText read_png_text(const std::string& png) {
  PngText out;
  if (!is_png(png)) return out;
  std::size_t at = kSignatureSize;
  while (at + 12 <= png.size()) {
    const std::uint32_t length = get_u32(png, at);
    if (at + 12 + length > png.size()) break;
    const std::string type = png.substr(at + 4, 4);
    if (type == "tEXt") {
      const std::string body = png.substr(at + 8, length);
      const std::size_t zero = body.find('\0');
      if (zero != std::string::npos) out.emplace_back(body.substr(0, zero), body.substr(zero + 1));
    }
    if (type == "IEND") break;
    at += 12 + length;
  }
  return out;
}

}  // namespace shapeproc::render

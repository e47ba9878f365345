#pragma once
// A small GIF89a decoder for tests: header, colour tables, graphic control and NETSCAPE loop
// extensions, LZW image data, and frames composited onto a canvas the way browsers show them
// (sub-rectangles, transparent index, disposal). Not interlaced images; enough to check what
// Pak's GIF writer produces.
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace pak::testing {

struct GifPixel {
  int r = 0, g = 0, b = 0, a = 0;
};

struct GifFrame {
  int delay = 0;                 // hundredths of a second
  std::vector<GifPixel> canvas;  // the whole picture after this frame, width x height
};

struct Gif {
  int width = 0, height = 0;
  std::vector<std::uint8_t> globalPalette;  // r g b r g b …
  std::optional<int> loopCount;             // NETSCAPE2.0 extension: 0 = forever
  std::vector<GifFrame> frames;
  GifPixel at(std::size_t frame, int x, int y) const {
    return frames.at(frame).canvas.at(static_cast<std::size_t>(y) * width + x);
  }
  bool paletteHas(int r, int g, int b) const {
    for (std::size_t i = 0; i + 2 < globalPalette.size(); i += 3)
      if (globalPalette[i] == r && globalPalette[i + 1] == g && globalPalette[i + 2] == b) return true;
    return false;
  }
};

namespace gif_detail {

class Reader {
 public:
  explicit Reader(std::vector<std::uint8_t> bytes) : bytes_(std::move(bytes)) {}
  std::uint8_t byte() {
    if (at_ >= bytes_.size()) throw std::runtime_error("GIF: unexpected end of data");
    return bytes_[at_++];
  }
  int word() {
    int low = byte();
    return low | byte() << 8;
  }
  std::vector<std::uint8_t> take(std::size_t n) {
    std::vector<std::uint8_t> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(byte());
    return out;
  }
  // Data sub-blocks up to the zero-length terminator, joined.
  std::vector<std::uint8_t> subBlocks() {
    std::vector<std::uint8_t> out;
    for (std::uint8_t size = byte(); size != 0; size = byte()) {
      std::vector<std::uint8_t> block = take(size);
      out.insert(out.end(), block.begin(), block.end());
    }
    return out;
  }

 private:
  std::vector<std::uint8_t> bytes_;
  std::size_t at_ = 0;
};

// Variable-width LZW codes, least significant bit first, as GIF packs them.
inline std::vector<std::uint8_t> decodeLzw(const std::vector<std::uint8_t>& data, int minimumCodeSize,
                                           std::size_t expected) {
  const int clear = 1 << minimumCodeSize, end = clear + 1;
  std::vector<std::vector<std::uint8_t>> table;
  auto reset = [&] {
    table.assign(static_cast<std::size_t>(end) + 1, {});
    for (int i = 0; i < clear; ++i) table[i] = {static_cast<std::uint8_t>(i)};
  };
  reset();
  int codeSize = minimumCodeSize + 1;
  std::size_t bit = 0;
  std::vector<std::uint8_t> out;
  int previous = -1;
  while (bit + codeSize <= data.size() * 8) {
    int code = 0;
    for (int i = 0; i < codeSize; ++i, ++bit) code |= ((data[bit / 8] >> (bit % 8)) & 1) << i;
    if (code == clear) {
      reset();
      codeSize = minimumCodeSize + 1;
      previous = -1;
      continue;
    }
    if (code == end) break;
    std::vector<std::uint8_t> entry;
    if (code < static_cast<int>(table.size()) && (code < clear || code > end)) {
      entry = table[code];
    } else if (code == static_cast<int>(table.size()) && previous >= 0) {
      entry = table[previous];
      entry.push_back(table[previous][0]);
    } else {
      throw std::runtime_error("GIF: bad LZW code " + std::to_string(code));
    }
    out.insert(out.end(), entry.begin(), entry.end());
    if (previous >= 0 && table.size() < 4096) {
      std::vector<std::uint8_t> added = table[previous];
      added.push_back(entry[0]);
      table.push_back(std::move(added));
    }
    if (static_cast<int>(table.size()) == (1 << codeSize) && codeSize < 12) ++codeSize;
    previous = code;
  }
  if (out.size() < expected) throw std::runtime_error("GIF: image data too short");
  out.resize(expected);
  return out;
}

}  // namespace gif_detail

inline Gif decodeGif(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  gif_detail::Reader in(std::vector<std::uint8_t>((std::istreambuf_iterator<char>(file)), {}));
  Gif gif;
  std::vector<std::uint8_t> signature = in.take(6);
  if (std::string(signature.begin(), signature.end()) != "GIF89a") throw std::runtime_error("GIF: not GIF89a");
  gif.width = in.word();
  gif.height = in.word();
  std::uint8_t packed = in.byte();
  in.byte();  // background colour index
  in.byte();  // aspect ratio
  if (packed & 0x80) gif.globalPalette = in.take(3u * (2u << (packed & 7)));

  std::vector<GifPixel> canvas(static_cast<std::size_t>(gif.width) * gif.height);
  int delay = 0, disposal = 0;
  int transparent = -1;  // the graphic control's transparent index, -1: none
  for (;;) {
    std::uint8_t block = in.byte();
    if (block == 0x3b) break;  // trailer
    if (block == 0x21) {
      std::uint8_t label = in.byte();
      std::vector<std::uint8_t> data = in.subBlocks();
      if (label == 0xf9 && data.size() >= 4) {  // graphic control
        disposal = (data[0] >> 2) & 7;
        delay = data[1] | data[2] << 8;
        transparent = (data[0] & 1) ? data[3] : -1;
      } else if (label == 0xff && data.size() >= 14 && std::string(data.begin(), data.begin() + 11) == "NETSCAPE2.0") {
        gif.loopCount = data[12] | data[13] << 8;
      }
      continue;
    }
    if (block != 0x2c) throw std::runtime_error("GIF: unknown block " + std::to_string(block));
    int left = in.word(), top = in.word(), width = in.word(), height = in.word();
    std::uint8_t imagePacked = in.byte();
    if (imagePacked & 0x40) throw std::runtime_error("GIF: interlaced images are not supported here");
    std::vector<std::uint8_t> palette = gif.globalPalette;
    if (imagePacked & 0x80) palette = in.take(3u * (2u << (imagePacked & 7)));
    int minimumCodeSize = in.byte();
    std::vector<std::uint8_t> indices =
        gif_detail::decodeLzw(in.subBlocks(), minimumCodeSize, static_cast<std::size_t>(width) * height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        int index = indices[static_cast<std::size_t>(y) * width + x];
        if (index == transparent) continue;
        if (left + x >= gif.width || top + y >= gif.height) continue;
        if (3u * index + 2 >= palette.size()) throw std::runtime_error("GIF: index outside the palette");
        canvas[static_cast<std::size_t>(top + y) * gif.width + left + x] = {palette[3 * index], palette[3 * index + 1],
                                                                           palette[3 * index + 2], 255};
      }
    gif.frames.push_back({delay, canvas});
    if (disposal == 2)  // restore to background: clear the frame's rectangle for the next one
      for (int y = top; y < std::min(top + height, gif.height); ++y)
        for (int x = left; x < std::min(left + width, gif.width); ++x) canvas[static_cast<std::size_t>(y) * gif.width + x] = {};
    delay = 0;
    disposal = 0;
    transparent = -1;
  }
  return gif;
}

}  // namespace pak::testing

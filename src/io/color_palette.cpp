// Median cut (Heckbert 1982) over a coarse histogram: boxes of colour cells are split at the
// pixel-weighted median of their longest side until there are enough boxes; each box gives the
// mean colour of its pixels.
#include "io/color_palette.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <limits>

namespace pak::color_palette {
namespace {

constexpr int kCells = 32 * 32 * 32;

int cellOf(std::uint8_t r, std::uint8_t g, std::uint8_t b) { return (r >> 3) << 10 | (g >> 3) << 5 | (b >> 3); }

struct Entry {
  std::array<double, 3> mean;  // exact mean colour of the cell's pixels
  std::uint64_t count;
  std::array<std::uint64_t, 3> sum;
};

struct Bucket {
  std::size_t begin, end;  // entries[begin, end)
  std::uint64_t count = 0;
  int axis = 0;            // longest side
  double range = 0.0;      // its length
  double score() const { return end - begin > 1 ? static_cast<double>(count) * range : -1.0; }
};

void measure(Bucket& bucket, const std::vector<Entry>& entries) {
  std::array<double, 3> lo{255, 255, 255}, hi{0, 0, 0};
  bucket.count = 0;
  for (std::size_t i = bucket.begin; i < bucket.end; ++i) {
    bucket.count += entries[i].count;
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], entries[i].mean[c]);
      hi[c] = std::max(hi[c], entries[i].mean[c]);
    }
  }
  bucket.axis = 0;
  for (int c = 1; c < 3; ++c)
    if (hi[c] - lo[c] > hi[bucket.axis] - lo[bucket.axis]) bucket.axis = c;
  bucket.range = hi[bucket.axis] - lo[bucket.axis];
}

Rgb meanColour(const Bucket& bucket, const std::vector<Entry>& entries) {
  std::array<std::uint64_t, 3> sum{0, 0, 0};
  for (std::size_t i = bucket.begin; i < bucket.end; ++i)
    for (int c = 0; c < 3; ++c) sum[c] += entries[i].sum[c];
  auto channel = [&](int c) { return static_cast<std::uint8_t>((sum[c] + bucket.count / 2) / bucket.count); };
  return {channel(0), channel(1), channel(2)};
}

}  // namespace

ColorHistogram::ColorHistogram() : cells_(kCells) {}

void ColorHistogram::add(const RgbaImage& image, std::optional<Rgb> skip) {
  const std::uint8_t* p = image.rgba.data();
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t i = 0; i < pixels; ++i, p += 4) {
    if (p[3] < 128) continue;
    if (skip && p[0] == skip->r && p[1] == skip->g && p[2] == skip->b) continue;
    Cell& cell = cells_[cellOf(p[0], p[1], p[2])];
    ++cell.count;
    cell.r += p[0];
    cell.g += p[1];
    cell.b += p[2];
  }
}

std::vector<Rgb> medianCut(const ColorHistogram& histogram, int maxColors, const std::vector<Rgb>& fixed) {
  std::vector<Rgb> palette = fixed;
  const int wanted = maxColors - static_cast<int>(fixed.size());
  std::vector<Entry> entries;
  for (const ColorHistogram::Cell& cell : histogram.cells())
    if (cell.count > 0) {
      double n = static_cast<double>(cell.count);
      entries.push_back({{cell.r / n, cell.g / n, cell.b / n}, cell.count, {cell.r, cell.g, cell.b}});
    }
  if (wanted <= 0 || entries.empty()) return palette;

  std::vector<Bucket> buckets{{0, entries.size()}};
  measure(buckets[0], entries);
  while (static_cast<int>(buckets.size()) < wanted) {
    auto widest = std::max_element(buckets.begin(), buckets.end(),
                                   [](const Bucket& a, const Bucket& b) { return a.score() < b.score(); });
    if (widest->score() <= 0.0) break;  // every box is one colour cell (or one colour)
    Bucket bucket = *widest;
    auto first = entries.begin() + static_cast<std::ptrdiff_t>(bucket.begin);
    auto last = entries.begin() + static_cast<std::ptrdiff_t>(bucket.end);
    const int axis = bucket.axis;
    std::sort(first, last, [axis](const Entry& a, const Entry& b) { return a.mean[axis] < b.mean[axis]; });
    // The pixel-weighted median, keeping at least one cell on each side.
    std::uint64_t seen = 0;
    std::size_t split = bucket.begin + 1;
    for (std::size_t i = bucket.begin; i + 1 < bucket.end; ++i) {
      seen += entries[i].count;
      split = i + 1;
      if (2 * seen >= bucket.count) break;
    }
    Bucket low{bucket.begin, split}, high{split, bucket.end};
    measure(low, entries);
    measure(high, entries);
    *widest = low;
    buckets.push_back(high);
  }
  for (const Bucket& bucket : buckets) palette.push_back(meanColour(bucket, entries));
  return palette;
}

NearestColor::NearestColor(std::vector<Rgb> palette, int first)
    : palette_(std::move(palette)), first_(first), cache_(std::size_t{1} << 24, 0xffff) {
  assert(first_ < static_cast<int>(palette_.size()) && palette_.size() <= 256);
}

std::uint8_t NearestColor::operator()(Rgb colour) {
  std::uint16_t& cached = cache_[static_cast<std::size_t>(colour.r) << 16 | colour.g << 8 | colour.b];
  if (cached != 0xffff) return static_cast<std::uint8_t>(cached);
  int best = first_;
  int bestDistance = std::numeric_limits<int>::max();
  for (int i = first_; i < static_cast<int>(palette_.size()); ++i) {
    int dr = colour.r - palette_[i].r, dg = colour.g - palette_[i].g, db = colour.b - palette_[i].b;
    int distance = dr * dr + dg * dg + db * db;
    if (distance < bestDistance) {
      bestDistance = distance;
      best = i;
    }
  }
  cached = static_cast<std::uint16_t>(best);
  return static_cast<std::uint8_t>(best);
}

}  // namespace pak::color_palette

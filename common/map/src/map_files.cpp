#include "scanfilter/map_files.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "scanfilter/input_error.hpp"
#include "scanfilter/map_picture.hpp"
#include "scanfilter/png_image.hpp"

namespace scanfilter {

namespace {

constexpr char kStateMagic[8] = {'S', 'F', 'M', 'A', 'P', '0', '0', '1'};

// Writes through a temporary file and renames it into place.
template <typename Write>
void writeAtomically(const std::string& path, Write&& write) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError(tmp, 0, "", std::string("cannot open for writing: ") + std::strerror(errno));
    write(out);
    out.flush();
    if (!out) throw InputError(tmp, 0, "", "write failed");
  }
  std::filesystem::rename(tmp, path);
}

int pgmValue(const OccupancyGrid& grid, CellIndex c) {
  const float l = grid.logOdds(c);
  if (l == 0.0f) return MapServerGrey::kUnknown;
  const double p = grid.probability(c);
  if (p > grid.params().occupied_threshold) return MapServerGrey::kOccupied;
  if (p < grid.params().free_threshold) return MapServerGrey::kFree;
  return MapServerGrey::kUnknown;
}

}  // namespace

PngImage mapImage(const OccupancyGrid& grid, const CellBox& box) {
  const int width = static_cast<int>(box.width()), height = static_cast<int>(box.height());
  PngImage png(std::max(width, 1), std::max(height, 1));
  for (int row = 0; row < height; ++row)
    for (int col = 0; col < width; ++col) {
      const auto v = static_cast<std::uint8_t>(pgmValue(grid, {box.lo.x + col, box.hi.y - row}));
      png.set(col, row, {v, v, v});
    }
  return png;
}

void saveMap(const OccupancyGrid& grid, const std::string& base, const std::string& note, const std::string& title) {
  const CellBox box = grid.bounds();
  const auto width = static_cast<int>(box.width()), height = static_cast<int>(box.height());
  const std::string stem = std::filesystem::path(base).filename().string();
  // Image rows run from the top (high y) down; the origin is the lower-left cell's corner.
  writeAtomically(base + ".pgm", [&](std::ofstream& out) {
    out << "P5\n# scanfilter occupancy map\n" << width << " " << height << "\n255\n";
    for (int row = 0; row < height; ++row)
      for (int col = 0; col < width; ++col)
        out.put(static_cast<char>(pgmValue(grid, {box.lo.x + col, box.hi.y - row})));
  });
  const Eigen::Vector2d origin = grid.cellCentre(box.lo) - Eigen::Vector2d::Constant(grid.params().resolution / 2);
  writeAtomically(base + ".yaml", [&](std::ofstream& out) {
    out << "image: " << stem << ".pgm\n"
        << "mode: trinary\n"
        << "resolution: " << grid.params().resolution << "\n"
        << "origin: [" << origin.x() << ", " << origin.y() << ", 0.0]\n"
        << "negate: 0\n"
        << "occupied_thresh: " << grid.params().occupied_threshold << "\n"
        << "free_thresh: " << grid.params().free_threshold << "\n";
  });
  // PngImage::save writes BASE.png.partial and renames it, as the files above.
  mapPicture({mapImage(grid, box)}, grid.params().resolution, title).save(base + ".png");
  writeAtomically(base + ".logodds", [&](std::ofstream& out) {
    out.write(kStateMagic, sizeof kStateMagic);
    const double resolution = grid.params().resolution;
    out.write(reinterpret_cast<const char*>(&resolution), sizeof resolution);
    out.write(reinterpret_cast<const char*>(&box.lo), sizeof box.lo);
    out.write(reinterpret_cast<const char*>(&box.hi), sizeof box.hi);
    for (std::int32_t y = box.lo.y; y <= box.hi.y; ++y)
      for (std::int32_t x = box.lo.x; x <= box.hi.x; ++x) {
        const float l = grid.logOdds({x, y});
        out.write(reinterpret_cast<const char*>(&l), sizeof l);
      }
    out << note;
  });
}

std::string loadMapState(OccupancyGrid& grid, const std::string& base) {
  const std::string path = base + ".logodds";
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", "cannot open saved map state");
  char magic[sizeof kStateMagic];
  double resolution = 0;
  CellBox box;
  in.read(magic, sizeof magic);
  in.read(reinterpret_cast<char*>(&resolution), sizeof resolution);
  in.read(reinterpret_cast<char*>(&box.lo), sizeof box.lo);
  in.read(reinterpret_cast<char*>(&box.hi), sizeof box.hi);
  if (!in || std::string(magic, sizeof magic) != std::string(kStateMagic, sizeof kStateMagic))
    throw InputError(path, 0, "", "not a scanfilter map state file");
  if (resolution != grid.params().resolution)
    throw InputError(path, 0, "resolution", "saved at " + std::to_string(resolution) + " m, configured " +
                                                std::to_string(grid.params().resolution) + " m");
  for (std::int32_t y = box.lo.y; y <= box.hi.y; ++y)
    for (std::int32_t x = box.lo.x; x <= box.hi.x; ++x) {
      float l = 0;
      in.read(reinterpret_cast<char*>(&l), sizeof l);
      if (!in) throw InputError(path, 0, "", "truncated map state");
      if (l != 0.0f) grid.setLogOdds({x, y}, l);
    }
  grid.takeChanged();
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};  // the note
}

}  // namespace scanfilter

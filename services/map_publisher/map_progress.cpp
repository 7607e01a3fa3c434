#include "map_progress.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "scanfilter/input_error.hpp"

namespace scanfilter::map_service {

MapProgress MapProgress::load(const std::string& base) {
  const std::string path = base + ".progress";
  MapProgress progress;
  if (!std::filesystem::exists(path)) return progress;
  std::ifstream in(path);
  std::string key;
  long long integrated = -1, last = -1;
  in >> key >> integrated;
  if (!in || key != "scans_integrated:" || integrated < 0)
    throw InputError(path, 1, "scans_integrated", "expected \"scans_integrated: <count>\"");
  progress.scans_integrated = static_cast<std::uint64_t>(integrated);
  if (in >> key >> last) {
    if (key != "last_sequence:" || last < 0) throw InputError(path, 2, "last_sequence", "expected \"last_sequence: <n>\"");
    progress.last_sequence = static_cast<std::uint64_t>(last);
  }
  return progress;
}

void MapProgress::save(const std::string& base) const {
  const std::string path = base + ".progress", tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << "scans_integrated: " << scans_integrated << "\n";
    if (last_sequence) out << "last_sequence: " << *last_sequence << "\n";
    if (!out) throw std::runtime_error(tmp + ": cannot write the map progress");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace scanfilter::map_service

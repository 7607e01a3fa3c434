#include "map_progress.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "scanfilter/input_error.hpp"

namespace scanfilter::map_service {

std::string MapProgress::toText() const {
  std::string text = "scans_integrated: " + std::to_string(scans_integrated) + "\n";
  if (last_sequence) text += "last_sequence: " + std::to_string(*last_sequence) + "\n";
  return text;
}

MapProgress MapProgress::parse(const std::string& text, const std::string& origin) {
  std::istringstream in(text);
  MapProgress progress;
  std::string key;
  long long integrated = -1, last = -1;
  in >> key >> integrated;
  if (!in || key != "scans_integrated:" || integrated < 0)
    throw InputError(origin, 1, "scans_integrated", "expected \"scans_integrated: <count>\"");
  progress.scans_integrated = static_cast<std::uint64_t>(integrated);
  if (in >> key >> last) {
    if (key != "last_sequence:" || last < 0) throw InputError(origin, 2, "last_sequence", "expected \"last_sequence: <n>\"");
    progress.last_sequence = static_cast<std::uint64_t>(last);
  }
  return progress;
}

MapProgress MapProgress::load(const std::string& base) {
  const std::string path = base + ".progress";
  if (!std::filesystem::exists(path)) return {};
  std::ifstream in(path);
  return parse({std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()}, path);
}

void MapProgress::save(const std::string& base) const {
  const std::string path = base + ".progress", tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::trunc);
    out << toText();
    if (!out) throw std::runtime_error(tmp + ": cannot write the map progress");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace scanfilter::map_service

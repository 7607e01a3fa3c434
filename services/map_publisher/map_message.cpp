#include "map_message.hpp"

#include "scanfilter/dds/scan_message.hpp"

namespace scanfilter::dds_io {

namespace {
// The grid's ROS values over a box of cells, row by row from its lower left.
template <typename Data>
void copyCells(const OccupancyGrid& grid, const CellBox& box, Data& data) {
  data.resize(static_cast<std::size_t>(box.width() * box.height()));
  std::size_t k = 0;
  for (std::int32_t y = box.lo.y; y <= box.hi.y; ++y)
    for (std::int32_t x = box.lo.x; x <= box.hi.x; ++x) data[k++] = static_cast<char>(grid.rosValue({x, y}));
}
}  // namespace

void toMapMsg(const OccupancyGrid& grid, const std::string& frame_id, MapMsg& out) {
  const CellBox box = grid.bounds();
  out.header().stamp(wallClockNow());
  out.header().frame_id(frame_id);
  out.info().map_load_time(wallClockNow());
  out.info().resolution(static_cast<float>(grid.params().resolution));
  out.info().width(static_cast<uint32_t>(box.width()));
  out.info().height(static_cast<uint32_t>(box.height()));
  const Eigen::Vector2d corner = grid.cellCentre(box.lo) - Eigen::Vector2d::Constant(grid.params().resolution / 2);
  out.info().origin().position().x(corner.x());
  out.info().origin().position().y(corner.y());
  out.info().origin().orientation().w(1.0);
  copyCells(grid, box, out.data());
}

void toUpdateMsg(const OccupancyGrid& grid, const CellBox& changed, const std::string& frame_id, MapUpdateMsg& out) {
  out.header().stamp(wallClockNow());
  out.header().frame_id(frame_id);
  out.x(changed.lo.x - grid.bounds().lo.x);
  out.y(changed.lo.y - grid.bounds().lo.y);
  out.width(static_cast<uint32_t>(changed.width()));
  out.height(static_cast<uint32_t>(changed.height()));
  copyCells(grid, changed, out.data());
}

}  // namespace scanfilter::dds_io

#include "real_consistency_report.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "scanfilter/accuracy/comparison_families.hpp"
#include "scanfilter/reobservation_picture.hpp"
#include "table_numbers.hpp"

namespace scanfilter::cli {

namespace {

constexpr int kPicturePixels = 1600;  // the map's longer side: 5 cm returns still apart on a 60 m floor
const char* const kShadowsFamily = "laser_filters shadows";
constexpr double kShadowsNeighbours = 1.0;  // bench-accuracy's tuned value, the comparison

ConsistencyFilter fromFamily(const accuracy::FilterFamily& family, const accuracy::ParamValues& values,
                             const std::string& name) {
  std::string parameters = accuracy::describe(family, values);
  parameters.insert(parameters.begin(), '`');
  parameters.push_back('`');
  return {name, parameters, [family, values](const SensorInfo& sensor) { return family.build(values, sensor); }};
}

// "6.9" (percent, one decimal) or "-" when there is nothing to divide.
std::string share(double v) { return std::isnan(v) ? "-" : fmt("%.1f", 100.0 * v); }
std::string shareWithUnit(double v) { return std::isnan(v) ? "-" : pct(v); }
std::string ratio(double v) { return std::isnan(v) ? "-" : std::isinf(v) ? "inf" : fmt("%.2f", v); }

}  // namespace

std::vector<ConsistencyFilter> consistencyFilters(const FilterConfig& ours, const std::optional<FilterConfig>& literal) {
  const std::vector<accuracy::FilterFamily> families = accuracy::comparisonFamilies(ours);
  std::vector<ConsistencyFilter> out;
  const auto defaults = [](const accuracy::FilterFamily& f) { return accuracy::sweepPoints(f, 1).front(); };
  out.push_back(fromFamily(families.front(), defaults(families.front()), families.front().name + " (default)"));
  if (literal)
    out.push_back({families.front().name + " (paper literal)", "config/filter-paper-literal.yaml",
                   [config = *literal](const SensorInfo& sensor) { return accuracy::makeTwoStepFilter(config, sensor); }});
  for (std::size_t f = 1; f < families.size(); ++f) {
    out.push_back(fromFamily(families[f], defaults(families[f]), families[f].name + " (default)"));
    if (families[f].name != kShadowsFamily) continue;
    accuracy::ParamValues one_neighbour = defaults(families[f]);
    one_neighbour.at("neighbors") = kShadowsNeighbours;
    out.push_back(fromFamily(families[f], one_neighbour, families[f].name + " (neighbors 1)"));
  }
  return out;
}

void RealConsistencyReport::add(const sim::LabelledLog& log, const std::string& picture_path,
                                const std::string& picture_link) {
  const auto start = std::chrono::steady_clock::now();
  const MultiviewConsistency measure(log.scans, log.sensor);
  std::cerr << "  multi-view consistency: "
            << fmt("%.1f s", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()) << "\n";
  // The harness takes a list of logs.
  const std::vector<sim::LabelledLog> harness_input{log};
  LogResult result{log.name, {}, {}};
  for (std::size_t f = 0; f < filters_.size(); ++f) {
    accuracy::LogLabels labels;
    accuracy::scoreFilter(filters_[f].make, harness_input, &labels);
    result.scores.push_back(measure.score(labels.front()));
    if (f != 0 || picture_path.empty()) continue;
    drawRemovalsByReobservation(log.scans, log.sensor, measure.reobservation(), labels.front(),
                                log.name + ": removed by " + filters_[f].name, kPicturePixels)
        .save(picture_path);
    result.picture_link = picture_link;
  }
  logs_.push_back(std::move(result));
}

void RealConsistencyReport::overallTable(std::ostream& out) const {
  out << "| log | filter | returns | removed | re-observed | removed of re-observed | removed of never re-observed | "
         "selectivity |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& log : logs_)
    for (std::size_t f = 0; f < filters_.size(); ++f) {
      const ConsistencyCounts& c = log.scores[f].all;
      out << "| " << log.name << " | " << filters_[f].name << " | " << c.returns << " | "
          << shareWithUnit(c.removedShare()) << " | " << shareWithUnit(c.reobservedShare()) << " | "
          << shareWithUnit(c.removedOfReobserved()) << " | " << shareWithUnit(c.removedOfNotReobserved()) << " | "
          << ratio(c.selectivity()) << " |\n";
    }
}

template <std::size_t N>
void RealConsistencyReport::bandTable(std::ostream& out, const char* title,
                                      std::array<ConsistencyCounts, N> ConsistencyScore::*bands,
                                      std::string (*band_name)(std::size_t)) const {
  out << "\n" << title << ": per filter, % removed of re-observed / of never re-observed returns.\n\n"
      << "| log | band | returns | re-observed |";
  for (const auto& f : filters_) out << " " << f.name << " |";
  out << "\n|---|---|---|---|";
  for (std::size_t f = 0; f < filters_.size(); ++f) out << "---|";
  out << "\n";
  for (const auto& log : logs_)
    for (std::size_t b = 0; b < N; ++b) {
      // The returns and their re-observation are the log's, whatever filter ran.
      const ConsistencyCounts& band = (log.scores.front().*bands)[b];
      out << "| " << log.name << " | " << band_name(b) << " | " << band.returns << " | "
          << shareWithUnit(band.reobservedShare()) << " |";
      for (const auto& score : log.scores) {
        const ConsistencyCounts& c = (score.*bands)[b];
        out << " " << share(c.removedOfReobserved()) << " / " << share(c.removedOfNotReobserved()) << " |";
      }
      out << "\n";
    }
}

void RealConsistencyReport::write(std::ostream& out) const {
  const MultiviewParams p;
  out << "Multi-view consistency: every return in a " << p.cell_size << " m grid; re-observed when the " << 2 * p.neighbourhood_cells + 1
      << " x " << 2 * p.neighbourhood_cells + 1 << " cells around it were hit from at least " << p.min_viewpoints
      << " sensor positions (rounded to " << p.position_cell << " m) neither its own nor adjacent to it. "
      << "Selectivity: removed share of never re-observed returns over removed share of re-observed ones.\n\n";
  overallTable(out);
  bandTable(out, "By range", &ConsistencyScore::by_range, rangeBandName);
  bandTable(out, "By incidence (beam against the surface normal from the neighbouring returns)",
            &ConsistencyScore::by_incidence, incidenceBandName);
  out << "\n| filter | parameters |\n|---|---|\n";
  for (const auto& f : filters_) out << "| " << f.name << " | " << f.parameters << " |\n";
  out << "\n| log | removed by " << filters_.front().name << ": red re-observed, blue never re-observed |\n|---|---|\n";
  for (const auto& log : logs_)
    out << "| " << log.name << " | "
        << (log.picture_link.empty() ? "-" : "![" + log.name + "](" + log.picture_link + ")") << " |\n";
}

}  // namespace scanfilter::cli

#pragma once
#include <array>
#include <cstdint>

namespace scanfilter {

// Simulator ground truth beside `truth`: why a beam's return is an artefact.
// The kinds are those an artefact's physics makes (docs/simulator.md), so
// that recall can be read per kind, as external labelled simulators report
// it. Scan logs carry it as `truth_cause` (docs/data-formats.md).
enum class ArtefactCause : std::uint8_t {
  kNone = 0,                  // not an artefact (valid, or no return)
  kMirrorGhost = 1,           // the beam mirrored off a smooth surface or a pane: a ghost behind it
  kThroughPane = 2,           // the beam went through a glass pane to what lies behind
  kEdgeMix = 3,               // the footprint straddled a depth step: a mixed return off every surface
  kThinObjectMix = 4,         // ... where part of the footprint lay on a thin leg
  kGrazingDisplacement = 5,   // a spot deformed at grazing incidence, displaced off its surface
  kJunctionDisplacement = 6,  // a spot at a junction of two walls, displaced off both
};

inline constexpr int kArtefactCauseCount = 7;

// The causes of an artefact (kNone left out), in code order: what a report
// lists.
inline constexpr std::array<ArtefactCause, kArtefactCauseCount - 1> kEveryArtefactCause = {
    ArtefactCause::kMirrorGhost,   ArtefactCause::kThroughPane,         ArtefactCause::kEdgeMix,
    ArtefactCause::kThinObjectMix, ArtefactCause::kGrazingDisplacement, ArtefactCause::kJunctionDisplacement};

inline constexpr bool isValidArtefactCause(int cause) { return cause >= 0 && cause < kArtefactCauseCount; }

inline constexpr const char* artefactCauseName(ArtefactCause cause) {
  switch (cause) {
    case ArtefactCause::kNone: return "none";
    case ArtefactCause::kMirrorGhost: return "mirror ghost";
    case ArtefactCause::kThroughPane: return "through a pane";
    case ArtefactCause::kEdgeMix: return "mixed at an edge";
    case ArtefactCause::kThinObjectMix: return "mixed at a thin object";
    case ArtefactCause::kGrazingDisplacement: return "displaced at grazing incidence";
    case ArtefactCause::kJunctionDisplacement: return "displaced at a junction";
  }
  return "unknown";
}

}  // namespace scanfilter

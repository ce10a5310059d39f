// tscmaa_non_edge: TSCMAA changes only what it claims to. Every frame, bit for bit,
//   - pixels outside the TAA share equal the CMAA output (TAA touched nothing else);
//   - pixels off the edge list equal the input colour (CMAA touched nothing else).
// Reads the CMAA image, the edge mask and the input ("current") beside the output.

#include "invariants/invariant_support.h"
#include "spec/taa_modes.h"

namespace taa::invariants {

namespace {

using namespace taa::spec;

class TscmaaNonEdge : public Invariant {
 public:
  void observe(const FrameView& f) override {
    if (!error_.empty()) return;
    error_ =
        requireCaptures(f, 3, {{Capture::Cmaa, 3}, {Capture::EdgeMask, 1}, {Capture::Current, 3}});
    if (!error_.empty()) return;
    ++frames_;
    const Image &out = *f.output, &cmaa = *f.capture(Capture::Cmaa),
                &edges = *f.capture(Capture::EdgeMask), &in = *f.capture(Capture::Current);
    for (int y = 0; y < out.height; ++y)
      for (int x = 0; x < out.width; ++x) {
        const auto bits = uint32_t(edges.at(x, y));
        if ((bits & mask::kTscmaaTaa) == 0u)
          note(sameRgbBits(out, cmaa, x, y), f.frame, x, y, nonTaa_, nonTaaBad_);
        if ((bits & mask::kTscmaaEdges) == 0u)
          note(sameRgbBits(cmaa, in, x, y), f.frame, x, y, nonEdge_, nonEdgeBad_);
      }
  }

  Outcome finish() override {
    Outcome o;
    o.values = {{"frames", double(frames_)},
                {"non_taa_pixels", double(nonTaa_)},
                {"non_taa_changed", double(nonTaaBad_)},
                {"non_edge_pixels", double(nonEdge_)},
                {"non_edge_changed", double(nonEdgeBad_)}};
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    if (frames_ == 0) {
      o.detail = "no frame to check";
      return o;
    }
    o.passed = nonTaaBad_ == 0 && nonEdgeBad_ == 0;
    o.detail = o.passed
                   ? "over " + std::to_string(frames_) + " frame(s), " + std::to_string(nonTaa_) +
                         " pixels outside the TAA share equal CMAA and " +
                         std::to_string(nonEdge_) + " off the edge list equal the input"
                   : std::to_string(nonTaaBad_) +
                         " pixel(s) outside the TAA share differ from CMAA, " +
                         std::to_string(nonEdgeBad_) +
                         " off the edge list differ from the input; first " + first_;
    return o;
  }

 private:
  void note(bool same, int frame, int x, int y, long& seen, long& bad) {
    ++seen;
    if (same) return;
    if (bad++ == 0 && first_.empty())
      first_ = "frame " + std::to_string(frame) + " pixel " + std::to_string(x) + "," +
               std::to_string(y);
  }

  std::string error_, first_;
  int frames_ = 0;
  long nonTaa_ = 0, nonTaaBad_ = 0, nonEdge_ = 0, nonEdgeBad_ = 0;
};

std::unique_ptr<Invariant> makeTscmaaNonEdge(const CheckedCase&) {
  return std::make_unique<TscmaaNonEdge>();
}

std::string tscmaaNonEdgeInapplicable(const CheckedCase& spec) {
  if (!modeRule(spec.taa.mode).tscmaa)
    return std::string("tscmaa_non_edge checks the TSCMAA passes, but taa.mode is ") +
           enumToString(spec.taa.mode) + "; set taa.mode to " +
           modeNames(modesWhere(&ModeRule::tscmaa)) + " or remove it from checks.invariants";
  if (spec.post.fxaa || spec.post.sharpen != Sharpen::None)
    return "tscmaa_non_edge compares the output with the CMAA image, but post.fxaa / post.sharpen "
           "change the "
           "output after TSCMAA; remove them or the invariant";
  return "";
}

}  // namespace

const InvariantInfo tscmaa_non_edge_invariant = {
    "tscmaa_non_edge",         {.captures = {Capture::Current, Capture::Cmaa, Capture::EdgeMask}},
    Frames::FromFrame,         nullptr,
    tscmaaNonEdgeInapplicable, makeTscmaaNonEdge};

}  // namespace taa::invariants

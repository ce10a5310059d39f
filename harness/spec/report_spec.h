// What the report shows of a case beyond golden against actual: a second parameter set
// rendered on the same replay (A/B), and a magnified region the case chooses. The
// harness's own part of the case format, like `checks`: the renderer never sees it.
#pragma once

#include <string>

#include "spec/fields.h"

namespace taa::spec {

// A region of the output in pixels; width 0 leaves the report's crop on the worst region.
struct ZoomSpec {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};

template <class V>
void fields(V& v, ZoomSpec& s) {
  const char* impl = "harness/run/golden_check.cpp";
  v.field("x", s.x, Range<int>{0, 8191},
          Meta{"left edge of the magnified region, output pixels", impl});
  v.field("y", s.y, Range<int>{0, 8191},
          Meta{"top edge of the magnified region, output pixels", impl});
  v.field("width", s.width, Range<int>{0, 8192},
          Meta{"width of the magnified region (0: the report magnifies the worst region instead)",
               impl});
  v.field("height", s.height, Range<int>{0, 8192}, Meta{"height of the magnified region", impl});
}

struct ReportSpec {
  std::string ab;                                   // a preset name; empty: no A/B
  std::string ab_presets = "presets/presets.json";  // relative to the case file's folder
  ZoomSpec zoom;
};

template <class V>
void fields(V& v, ReportSpec& s) {
  const char* impl = "harness/run/ab_run.cpp";
  v.field(
      "ab", s.ab,
      Meta{"A/B: also render the case with this preset merged in (a JSON merge patch from "
           "ab_presets) "
           "on the same replay; the report's split view compares the two outputs frame by frame",
           impl});
  v.field("ab_presets", s.ab_presets,
          Meta{"the presets file report.ab names a preset of, relative to the case file's folder",
               impl});
  v.object("zoom", s.zoom,
           Meta{"a region of the output the report magnifies, for every checked frame", ""});
}

}  // namespace taa::spec

// Blessing from the report: the summary row of a failing or stale case shows its first differing
// frame as thumbnails and a checkbox, and the panel under the summary turns the ticked cases and a
// reason into one `taa-harness bless --from DIR CASE... --reason '...'` command, built by the
// page's script from the folder it was opened from, so it works as well from a report unpacked
// from a CI artifact.
#include <cstdlib>
#include <string>

#include "report/html_parts.h"
#include "report/text_util.h"

namespace taa::report::detail {

namespace fs = std::filesystem;

namespace {

// The images of one differing frame; a side left empty has no image.
struct Thumbs {
  int frame = -1;
  std::string golden, goldenCaption, actual, actualCaption = "actual", diff;
  std::string anchor;    // the case section's element that shows the frame in full
  bool checked = false;  // a checked frame, measured pixel by pixel: it has a diff heatmap
};

bool differs(run::FrameStatus s) {
  return s == run::FrameStatus::Failed || s == run::FrameStatus::MissingGolden;
}

// The earliest frame that differs: a checked frame that failed (golden, actual and diff of one
// frame), or the sequence's first difference (its actual beside the nearest stored golden frame,
// which is another frame unless that frame was checked, when the checked frame wins the tie).
Thumbs firstDifferingFrame(const run::CaseResult& c, const std::string& id) {
  const run::FrameComparison* checked = nullptr;
  for (const auto& f : c.frames)
    if (differs(f.status) && (!checked || f.frame < checked->frame)) checked = &f;
  const auto& d = c.firstDifference;
  Thumbs t;
  if (d.frame >= 0 && !d.actual.empty() && (!checked || d.frame < checked->frame)) {
    t.frame = d.frame;
    t.actual = d.actual;
    t.actualCaption = "actual " + std::to_string(d.frame);
    t.anchor = id + "-first";
    const run::FirstDifference::Neighbour* nearest = nullptr;
    for (const auto& n : d.goldenNeighbours)
      if (!nearest || std::abs(n.frame - d.frame) < std::abs(nearest->frame - d.frame))
        nearest = &n;
    // Another frame of the sequence: its number says so beside the actual's.
    if (nearest) {
      t.golden = nearest->image;
      t.goldenCaption = "golden " + std::to_string(nearest->frame);
    }
    return t;
  }
  if (!checked) return t;
  t.frame = checked->frame;
  t.golden = checked->images.golden;
  t.goldenCaption = "golden";
  t.actual = checked->images.actual;
  t.diff = checked->images.diff;
  t.anchor = id + "-f" + std::to_string(checked->frame);
  t.checked = true;
  return t;
}

std::string thumb(const fs::path& dir, const std::string& rel, const std::string& caption) {
  std::string s = "<figure><figcaption>" + escapeMarkup(caption) + "</figcaption>";
  if (imageExists(dir, rel))
    s += "<img class=\"thumb\" src=\"" + encodePath(rel) + "\" alt=\"" + escapeMarkup(caption) +
         "\" loading=\"eager\">";
  else
    s += "<span class=\"thumb-none\">none</span>";
  return s + "</figure>";
}

}  // namespace

bool blessable(const run::CaseResult& c) {
  return (c.status == run::CaseStatus::Fail || c.status == run::CaseStatus::Stale) &&
         !c.file.empty();
}

std::string firstDifferenceThumbs(const run::CaseResult& c, const std::string& id,
                                  const fs::path& dir) {
  const Thumbs t = firstDifferingFrame(c, id);
  if (t.frame < 0) return "<span class=\"muted\">no differing frame</span>";
  const std::string frame = "frame " + std::to_string(t.frame);
  if (!imageExists(dir, t.golden) && !imageExists(dir, t.actual) && !imageExists(dir, t.diff))
    return "<a href=\"#" + t.anchor + "\">" + frame + "</a> <span class=\"muted\">(no images in " +
           "this run's folder)</span>";
  std::string s = "<a class=\"thumbs\" href=\"#" + t.anchor + "\" title=\"" + frame +
                  ": open in the case\"><span class=\"thumbs-frame\">" + frame + "</span>";
  s += thumb(dir, t.golden, t.goldenCaption.empty() ? "golden" : t.goldenCaption);
  s += thumb(dir, t.actual, t.actualCaption);
  if (t.checked) s += thumb(dir, t.diff, "diff");
  return s + "</a>";
}

std::string blessCheckbox(const run::CaseResult& c) {
  return "<input type=\"checkbox\" class=\"bless-pick\" data-case=\"" + escapeMarkup(c.name) +
         "\" data-file=\"" + escapeMarkup(c.file) + "\" aria-label=\"bless " +
         escapeMarkup(c.name) + "\">";
}

std::string blessPanel() {
  return "<div class=\"bless-from\" id=\"bless-from\">\n<h3>Bless ticked cases from this "
         "run</h3>\n<p class=\"muted\">When the new frames are right: tick the cases above, say "
         "why, and run the command where the goldens live. It takes the frames and hashes this "
         "run wrote into its folder, so it renders nothing and needs no Vulkan device. The run "
         "folder is the one this page was opened from; change it where the folder lies "
         "elsewhere.</p>\n<div class=\"bless-fields\"><label>run folder <input type=\"text\" "
         "id=\"bless-dir\" spellcheck=\"false\" placeholder=\"the folder of this report and "
         "its results.json\"></label><label>reason <input type=\"text\" id=\"bless-reason\" "
         "placeholder=\"why the new frames are right\"></label></div>\n"
         "<p class=\"bless-hint\" id=\"bless-hint\">The command shows once at least one case "
         "is ticked and a reason is typed.</p>\n<div class=\"bless\" id=\"bless-command\" "
         "hidden><code></code><button type=\"button\" class=\"copy\">copy</button></div>\n"
         "</div>\n";
}

}  // namespace taa::report::detail

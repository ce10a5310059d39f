#include "report/html_report.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

#include "report/fixture.h"
#include "report/html_parts.h"
#include "report/svg_plot.h"
#include "run/console.h"
#include "support/text.h"

namespace fs = std::filesystem;
using taa::report::renderHtmlReport;
using taa::report::writeHtmlReport;

namespace {

using taa::test::count;
using taa::test::readFile;

std::string percentDecode(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '%' && i + 2 < s.size()) {
      out += char(std::stoi(s.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += s[i];
    }
  }
  return out;
}

std::vector<std::string> attributeValues(const std::string& html, const std::string& attr) {
  std::vector<std::string> out;
  const std::regex re("\\s" + attr + "=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), re); it != std::sregex_iterator();
       ++it)
    out.push_back((*it)[1]);
  return out;
}

class ReportHtml : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = taa::test::freshDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    results_ = taa::test::sampleRun(dir_);
    writeHtmlReport(dir_ / "report.html", results_);
    html_ = readFile(dir_ / "report.html");
  }
  fs::path dir_;
  taa::run::RunResults results_;
  std::string html_;
};

TEST_F(ReportHtml, EveryImageExistsBesideTheReport) {
  const auto srcs = attributeValues(html_, "src");
  EXPECT_EQ(srcs.size(), count(html_, "<img "));
  // 2 checked frames with 6 images each plus the A/B pair, the golden-less actual, one frame
  // whose zoomed diff is missing, and the failing case's three thumbnails in the summary.
  EXPECT_EQ(srcs.size(), 8u + 8u + 7u + 1u + 3u);
  for (const auto& src : srcs) {
    EXPECT_FALSE(src.empty());
    EXPECT_NE(src[0], '/') << src;
    EXPECT_TRUE(fs::is_regular_file(dir_ / percentDecode(src))) << src;
  }
  // A placeholder, not a broken image.
  EXPECT_NE(html_.find("diff crop: missing img/deleted_zoom.png"), std::string::npos);
}

TEST_F(ReportHtml, NoExternalReferences) {
  std::string lower = html_;
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  for (const char* bad : {"http", "://", "url(", "@import", "<link", "<iframe", "src=\"//"})
    EXPECT_EQ(lower.find(bad), std::string::npos) << bad;
  for (const auto& href : attributeValues(html_, "href")) EXPECT_EQ(href[0], '#') << href;
  // Exactly one script element: the report's own, inline.
  EXPECT_EQ(count(lower, "<script"), 1u);
  EXPECT_EQ(count(lower, "<script>"), 1u);
}

TEST_F(ReportHtml, ListsCasesFailuresAndEscapesUserText) {
  for (const auto& c : results_.cases) {
    EXPECT_NE(html_.find(">" + c.name + "<"), std::string::npos) << c.name;
    EXPECT_NE(html_.find("data-case=\"" + c.name + "\""), std::string::npos) << c.name;
  }
  for (const char* label : {">PASS<", ">FAIL<", ">NO GOLDEN<", ">ERROR<", ">FAILED<", ">EXACT<"})
    EXPECT_NE(html_.find(label), std::string::npos) << label;
  EXPECT_NE(html_.find("<li>rmse 0.021 &gt; 0.01</li>"), std::string::npos);
  EXPECT_NE(html_.find("<li>flip_mean 0.08 &gt; 0.05</li>"), std::string::npos);
  EXPECT_NE(html_.find("residual 0.12 &gt; 0.05 after 8 frames"), std::string::npos);
  EXPECT_NE(html_.find("Thin geometry &lt;script&gt;alert(1)&lt;/script&gt; &amp; ghosting"),
            std::string::npos);
  EXPECT_NE(html_.find("&quot;&lt;bin&gt;&quot;"), std::string::npos);
  EXPECT_NE(html_.find("<code>taa-harness bless cases/moving_fence.json</code>"),
            std::string::npos);
  EXPECT_NE(html_.find("data-case-count=\"4\""), std::string::npos);
}

TEST_F(ReportHtml, MetricsShowNonFiniteValuesAndMarkFailures) {
  EXPECT_NE(html_.find("<td class=\"num\">inf</td>"), std::string::npos);  // PSNR of exact frame
  EXPECT_NE(html_.find("<td class=\"num bad\">nan</td>"), std::string::npos);
  EXPECT_NE(html_.find("<td class=\"num bad\">0.021</td>"), std::string::npos);
  EXPECT_NE(html_.find("<td class=\"num bad\">0.08</td>"), std::string::npos);
  EXPECT_EQ(count(html_, "num bad"), 3u);  // share over and max abs did not fail
  EXPECT_NE(html_.find("x 25, y 19, 12\xC3\x97"
                       "8 px"),
            std::string::npos);  // crop rectangle
  EXPECT_NE(html_.find("<td class=\"num\">1.250</td><td class=\"num\">1.500</td>"),
            std::string::npos);  // pass timing median, p95
}

TEST_F(ReportHtml, CaseWithoutFramesOrImagesStillRenders) {
  EXPECT_NE(html_.find("no frames were compared"), std::string::npos);
  EXPECT_NE(html_.find("A/B view needs both the golden and the actual image"), std::string::npos);
  EXPECT_NE(html_.find("golden frame 0: no image"), std::string::npos);
  EXPECT_EQ(count(html_, "<section class=\"case "), 4u);
  EXPECT_EQ(count(html_, "<svg "), 4u);  // error and frame-time curves of the two full cases
}

// The frame-time curve has a point for every frame the case rendered, the first included.
TEST_F(ReportHtml, FrameTimeCurvesHaveAPointPerFrame) {
  std::vector<size_t> points;
  const std::string group = "<g class=\"series\" data-name=\"frame time\">";
  for (size_t at = html_.find(group); at != std::string::npos; at = html_.find(group, at + 1)) {
    const size_t from = html_.find("<polyline points=\"", at);
    ASSERT_NE(from, std::string::npos);
    const size_t begin = from + std::string("<polyline points=\"").size();
    const std::string list = html_.substr(begin, html_.find('"', begin) - begin);
    points.push_back(size_t(std::count(list.begin(), list.end(), ',')));
  }
  std::vector<size_t> frames;
  for (const auto& c : results_.cases)
    if (!c.frameMs.empty()) frames.push_back(c.frameMs.size());
  EXPECT_EQ(points, frames);
  EXPECT_EQ(frames, (std::vector<size_t>{16, 12}));
}

// report.ab: B is a second replay's output. When it is missing the view must say so, not link
// an image that is not there.
TEST_F(ReportHtml, AnAbViewWithoutItsSecondOutputSaysSo) {
  taa::run::RunResults r = results_;
  taa::run::FrameImages& im = r.cases[0].frames[0].images;
  im.abLabel = "alpha 0.2";
  im.ab = "img/missing_ab.png";
  const std::string missing = renderHtmlReport(r, dir_);
  EXPECT_NE(missing.find("A/B of the second parameter set needs both outputs"), std::string::npos);
  EXPECT_EQ(missing.find("missing_ab.png"), std::string::npos);

  taa::writePngLinear8(dir_ / "img/present_ab.png", taa::test::testPicture(0.1f));
  im.ab = "img/present_ab.png";
  const std::string present = renderHtmlReport(r, dir_);
  EXPECT_EQ(present.find("needs both outputs"), std::string::npos);
  EXPECT_NE(present.find("src=\"img/present_ab.png\""), std::string::npos);
  EXPECT_NE(present.find("B: alpha 0.2"), std::string::npos);
}

TEST_F(ReportHtml, DeterministicAtomicAndExtendable) {
  EXPECT_EQ(renderHtmlReport(results_, dir_), html_);
  for (const auto& e : fs::directory_iterator(dir_))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();

  taa::report::ReportExtras extras;
  taa::report::PlotSeries s{.name = "runs", .x = {1, 2, 3}, .y = {0.3, 0.1, 0.2}};
  extras.sections.push_back(
      {"Error vs time <sweep>", "a & b", taa::report::svgPlot({s}, {.title = "sweep"}),
       taa::report::htmlTable({"config", "ms", "rmse"}, {{"a<b", "1.5", "inf"}, {"c"}})});
  const std::string withExtra = renderHtmlReport(results_, dir_, extras);
  EXPECT_NE(withExtra.find("<h2>Error vs time &lt;sweep&gt;</h2>"), std::string::npos);
  EXPECT_NE(withExtra.find("<p>a &amp; b</p>"), std::string::npos);
  EXPECT_NE(withExtra.find("<td>a&lt;b</td><td class=\"num\">1.5</td><td class=\"num\">inf</td>"),
            std::string::npos);
  EXPECT_NE(withExtra.find("<tr><td>c</td><td></td><td></td></tr>"), std::string::npos);
  EXPECT_LT(withExtra.find("class=\"extra\""), withExtra.find("<script>"));
}

TEST(ReportHtmlExtrasOnly, NoCaseSummaryOrContentsWithoutCases) {
  // The sweep writes a report of extra sections only: no "0 cases" line, no empty contents table.
  taa::run::RunResults none;
  none.device = "llvmpipe";
  taa::report::ReportExtras extras;
  extras.sections.push_back(
      {"Sweep", "note", "", taa::report::htmlTable({"preset"}, {{"default"}})});
  const std::string html = renderHtmlReport(none, fs::temp_directory_path(), extras);
  EXPECT_EQ(html.find("0 cases"), std::string::npos);
  EXPECT_EQ(html.find("class=\"summary\""), std::string::npos);
  EXPECT_EQ(html.find("class=\"toc\""), std::string::npos);
  EXPECT_EQ(html.find("fingerprint"), std::string::npos);
  EXPECT_NE(html.find("<h2>Sweep</h2>"), std::string::npos);
  EXPECT_NE(html.find("<dd>llvmpipe</dd>"), std::string::npos);
  // A run with cases keeps both.
  const auto dir = taa::test::freshDir("extras_only");
  const std::string full = renderHtmlReport(taa::test::sampleRun(dir), dir, extras);
  EXPECT_NE(full.find("4 cases:"), std::string::npos);
  EXPECT_NE(full.find("class=\"toc\""), std::string::npos);
}

TEST(ReportHtmlWrite, FailsLoudlyWhenTheFolderIsMissing) {
  EXPECT_THROW(writeHtmlReport("/nonexistent-dir/report.html", {}), std::runtime_error);
}

}  // namespace

TEST(ReportHtmlUserShader, CaseHeaderNamesTheShaderAndItsParameters) {
  const auto dir = taa::test::freshDir("user_shader_header");
  auto run = taa::test::sampleRun(dir);
  run.cases[0].resolve = "user shader mine.hlsl (hlsl, entry main), params: alpha=0.1 (float)";
  const std::string html = renderHtmlReport(run, dir);
  const size_t header = html.find("data-case=\"" + run.cases[0].name + "\"");
  ASSERT_NE(header, std::string::npos);
  const size_t shown =
      html.find("user shader mine.hlsl (hlsl, entry main), params: alpha=0.1 (float)");
  ASSERT_NE(shown, std::string::npos);
  // In the case's own header, before its first frame.
  EXPECT_LT(shown - header, html.find("<img", header) - header);
}

namespace {

// The summary row of case `name`: from its <tr> to the row's end.
std::string summaryRow(const std::string& html, const std::string& name) {
  const size_t link = html.find(">" + name + "</a></td>");
  if (link == std::string::npos) return "";
  const size_t start = html.rfind("<tr>", link);
  return html.substr(start, html.find("</tr>", link) - start);
}

}  // namespace

TEST(ReportBless, FailingRowShowsTheFirstFailedFramesThumbnailsAndACheckbox) {
  const auto dir = taa::test::freshDir("bless_thumbs");
  const auto run = taa::test::sampleRun(dir);
  const std::string html = renderHtmlReport(run, dir);
  const std::string fail = summaryRow(html, "moving_fence");
  // Frame 4 is within tolerance; frame 8 is the first that failed: golden, actual and diff of it,
  // linked to the frame in the case.
  EXPECT_NE(fail.find("href=\"#case-1-f8\""), std::string::npos) << fail;
  for (const char* img :
       {"img/fence_8_golden.png", "img/fence_8_actual.png", "img/fence_8_diff.png"})
    EXPECT_NE(fail.find("class=\"thumb\" src=\"" + std::string(img) + "\""), std::string::npos)
        << img;
  EXPECT_EQ(count(fail, "<img "), 3u);
  EXPECT_NE(fail.find("data-file=\"cases/moving_fence.json\""), std::string::npos);
  // Passing, golden-less and erroring cases offer nothing to bless.
  for (const char* name : {"static_sponza", "new_case", "broken_gltf"}) {
    const std::string row = summaryRow(html, name);
    ASSERT_FALSE(row.empty()) << name;
    EXPECT_EQ(row.find("bless-pick"), std::string::npos) << name;
    EXPECT_EQ(row.find("<img"), std::string::npos) << name;
  }
  EXPECT_EQ(count(html, "class=\"bless-pick\""), 1u);
  EXPECT_EQ(count(html, "id=\"bless-all\""), 1u);
  // The folder is the page's own (its script reads it), so the page holds no path of this run
  // and stays a function of the results; the command waits for ticks and a reason.
  EXPECT_NE(html.find("id=\"bless-dir\" spellcheck=\"false\" placeholder="), std::string::npos);
  EXPECT_EQ(html.find(dir.string()), std::string::npos);
  EXPECT_NE(html.find("id=\"bless-command\" hidden"), std::string::npos);
  EXPECT_NE(html.find("The command shows once at least one case is ticked and a reason is typed."),
            std::string::npos);
}

TEST(ReportBless, SequenceDifferenceBeforeTheCheckedFramesShowsItsActualAndNearestGolden) {
  const auto dir = taa::test::freshDir("bless_sequence");
  auto run = taa::test::sampleRun(dir);
  auto& c = run.cases[1];
  c.status = taa::run::CaseStatus::Stale;
  c.firstDifference.frame = 6;
  c.firstDifference.actual = taa::test::writeFrameImages(dir, "seq_6", true).actual;
  // Stored golden frames 4 and 9 around it: 4 is nearer.
  c.firstDifference.goldenNeighbours = {{4, "img/fence_4_golden.png"},
                                        {9, "img/static_15_golden.png"}};
  std::string row = summaryRow(renderHtmlReport(run, dir), "moving_fence");
  EXPECT_NE(row.find("href=\"#case-1-first\""), std::string::npos) << row;
  EXPECT_NE(row.find("frame 6"), std::string::npos);
  EXPECT_NE(row.find("<figcaption>golden 4</figcaption><img class=\"thumb\" "
                     "src=\"img/fence_4_golden.png\""),
            std::string::npos)
      << row;
  EXPECT_NE(row.find("<figcaption>actual 6</figcaption><img class=\"thumb\" "
                     "src=\"img/seq_6_actual.png\""),
            std::string::npos);
  EXPECT_EQ(row.find("<figcaption>diff"), std::string::npos)
      << "a sequence difference has no heatmap";
  EXPECT_EQ(count(row, "<img "), 2u);

  // Where the checked frame comes first, it wins: it has a diff of the same frame.
  c.firstDifference.frame = 8;
  row = summaryRow(renderHtmlReport(run, dir), "moving_fence");
  EXPECT_NE(row.find("href=\"#case-1-f8\""), std::string::npos) << row;
  EXPECT_EQ(count(row, "<img "), 3u);
}

TEST(ReportBless, RowsSayWhenTheRunWroteNoImagesOrNoFrameDiffered) {
  const auto dir = taa::test::freshDir("bless_fallback");
  auto run = taa::test::sampleRun(dir);
  auto noImages = run.cases[1];
  noImages.name = "no_images";
  for (auto& f : noImages.frames) f.images = {};
  auto invariantOnly = run.cases[1];
  invariantOnly.name = "invariant_only";
  invariantOnly.frames.pop_back();  // only the frame within tolerance is left
  auto missingDiff = run.cases[1];
  missingDiff.name = "missing_diff";
  missingDiff.frames.back().images.diff = "img/never_written.png";
  run.cases.push_back(noImages);
  run.cases.push_back(invariantOnly);
  run.cases.push_back(missingDiff);
  const std::string html = renderHtmlReport(run, dir);
  const std::string none = summaryRow(html, "no_images");
  EXPECT_NE(none.find("frame 8</a> <span class=\"muted\">(no images in this run's folder)"),
            std::string::npos)
      << none;
  EXPECT_EQ(none.find("<img"), std::string::npos);
  EXPECT_NE(summaryRow(html, "invariant_only").find("no differing frame"), std::string::npos);
  // One missing file leaves a placeholder in its place, not a broken image.
  const std::string partial = summaryRow(html, "missing_diff");
  EXPECT_EQ(count(partial, "<img "), 2u);
  EXPECT_NE(partial.find("<figcaption>diff</figcaption><span class=\"thumb-none\">none</span>"),
            std::string::npos)
      << partial;
  EXPECT_EQ(count(html, "class=\"bless-pick\""), 4u);
}

TEST(ReportBless, AllPassingRunHasNoBlessControls) {
  const auto dir = taa::test::freshDir("bless_none");
  auto run = taa::test::sampleRun(dir);
  run.cases = {run.cases[0], run.cases[2]};
  const std::string html = renderHtmlReport(run, dir);
  for (const char* id : {"id=\"bless-all\"", "class=\"bless-pick\"", "id=\"bless-from\"",
                         "<th>first differing frame</th>"})
    EXPECT_EQ(html.find(id), std::string::npos) << id;
}

TEST(ReportSequence, WorstLineSaysNoDifferenceInsteadOfFrameMinusOne) {
  const auto dir = taa::test::freshDir("sequence_worst");
  auto run = taa::test::sampleRun(dir);
  auto& q = run.cases[0].sequenceCheck;
  q.mode = "signature";
  q.frames = 16;  // worst frames stay -1: nothing differed
  EXPECT_NE(renderHtmlReport(run, dir).find(
                "quality signatures against tolerances (no positive for this environment) (no difference)"),
            std::string::npos);
  EXPECT_EQ(renderHtmlReport(run, dir).find("frame -1"), std::string::npos);
  using taa::run::sequenceWorst;  // the console and the report say it alike
  EXPECT_EQ(sequenceWorst(q), " (no difference)");
  q.worstMean = 0.00001234;
  q.worstMeanFrame = 3;
  EXPECT_EQ(sequenceWorst(q), " (worst: no cell differs, channel mean 1.23e-05 at frame 3)");
  q.worstCell = 2;
  q.worstCellFrame = 7;
  EXPECT_EQ(sequenceWorst(q), " (worst: cell 2/255 at frame 7, channel mean 1.23e-05 at frame 3)");
  q.worstMeanFrame = -1;
  EXPECT_EQ(sequenceWorst(q), " (worst: cell 2/255 at frame 7, no channel mean differs)");
  q.mode = "exact";
  EXPECT_EQ(sequenceWorst(q), "");
}

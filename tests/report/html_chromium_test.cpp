// Opens the report in headless Chromium (Debian's chromium package, installed by
// ci/install-deps.sh) and reads back what the page's own script found: whether every image
// decoded, whether the page rendered, and where the A/B divider went after a scripted zoom click,
// pointer press and two arrow keys; and the `bless --from` command the page builds for two ticked
// cases and a reason, which a POSIX shell must read back word for word.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>

#include "report/fixture.h"
#include "report/html_report.h"
#include "report/svg_plot.h"
#include "report/text_util.h"
#include "support/text.h"

namespace fs = std::filesystem;

namespace {

using taa::test::count;

std::string findChromium() {
  if (const char* env = std::getenv("TAA_CHROMIUM"); env && *env) return fs::exists(env) ? env : "";
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser", "/usr/bin/google-chrome"})
    if (fs::exists(p)) return p;
  return "";
}

std::string run(const std::string& command) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return "";
  std::string out;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  pclose(pipe);
  return out;
}

// The DOM after the page's scripts ran: no network (file:// only; features that phone home are
// off), a fresh profile so no state leaks between runs, virtual time so loading finishes fast.
std::string dumpDom(const std::string& chromium, const fs::path& profile, const std::string& url,
                    const fs::path& log) {
  return run("timeout 120 '" + chromium +
             "' --headless --no-sandbox --disable-gpu --disable-quic "
             "--no-first-run --disable-background-networking --disable-component-update "
             "--disable-sync --disable-extensions --user-data-dir='" +
             profile.string() + "' --virtual-time-budget=5000 --dump-dom '" + url + "' 2>'" +
             log.string() + "'");
}

std::map<std::string, std::string> bodyAttributes(const std::string& dom) {
  std::map<std::string, std::string> out;
  std::smatch body;
  if (!std::regex_search(dom, body, std::regex("<body([^>]*)>"))) return out;
  const std::string attrs = body[1];
  const std::regex attr("([\\w-]+)=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(attrs.begin(), attrs.end(), attr);
       it != std::sregex_iterator(); ++it)
    out[(*it)[1]] = (*it)[2];
  return out;
}

TEST(ReportChromium, RendersLoadsEveryImageAndMovesTheDivider) {
  const std::string chromium = findChromium();
  if (chromium.empty())
    GTEST_SKIP() << "chromium not found (apt-get install chromium, or set TAA_CHROMIUM)";
  const fs::path dir = fs::absolute(taa::test::freshDir("chromium"));
  const auto results = taa::test::sampleRun(dir);
  // The shape the error-versus-time sweep will have: a scatter, its Pareto front and a table.
  const std::vector<double> ms = {1.1, 1.6, 2.4, 3.9, 2.0, 5.2},
                            err = {0.05, 0.02, 0.012, 0.011, 0.03, 0.0105};
  taa::report::PlotSeries runs{
      .name = "configs", .x = ms, .y = err, .line = false, .markers = true};
  taa::report::PlotSeries front{.name = "Pareto front", .colour = "#c62828", .highlight = true};
  std::vector<std::vector<std::string>> rows;
  for (size_t i : taa::report::paretoFront(ms, err)) {
    front.x.push_back(ms[i]);
    front.y.push_back(err[i]);
  }
  for (size_t i = 0; i < ms.size(); ++i)
    rows.push_back({"config " + std::to_string(i), taa::report::formatNumber(ms[i]),
                    taa::report::formatNumber(err[i])});
  taa::report::ReportExtras extras;
  extras.sections.push_back({"Error versus run time", "Pareto front in red.",
                             taa::report::svgPlot({runs, front}, {.width = 560,
                                                                  .height = 260,
                                                                  .title = "sweep",
                                                                  .xLabel = "ms per frame",
                                                                  .yLabel = "RMSE",
                                                                  .logY = true,
                                                                  .yFromZero = false}),
                             taa::report::htmlTable({"config", "ms", "RMSE"}, rows)});
  taa::report::writeHtmlReport(dir / "report.html", results, extras);
  const std::string html = taa::report::renderHtmlReport(results, dir, extras);
  const size_t images = count(html, "<img ");

  const auto start = std::chrono::steady_clock::now();
  const std::string url = "file://" + taa::report::encodePath((dir / "report.html").string()) +
                          "#zoom=2&split=0.25&keys=ArrowRight,ArrowRight";
  const std::string dom = dumpDom(chromium, dir / "profile", url, dir / "chromium.log");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("chromium_seconds", std::to_string(seconds));
  ASSERT_NE(dom.find("</html>"), std::string::npos)
      << "no DOM from chromium; see " << (dir / "chromium.log");

  auto body = bodyAttributes(dom);
  EXPECT_EQ(body["data-render-ok"], "1");
  EXPECT_EQ(body["data-images-loaded"], std::to_string(images) + "/" + std::to_string(images))
      << "broken: " << body["data-images-broken"];
  EXPECT_EQ(body.count("data-js-error"), 0u) << body["data-js-error"];
  EXPECT_EQ(body["data-badges-tall"], "0");
  EXPECT_NE(dom.find("<h2>Error versus run time</h2>"), std::string::npos);
  // 2x zoom of the 48 px wide test frame; a press at a quarter of its width; two arrow keys move
  // the divider one image pixel each.
  EXPECT_EQ(body["data-split-width"], "96");
  EXPECT_EQ(body["data-split-after-pointer"], "0.2500");
  EXPECT_EQ(body["data-split-after-keys"], "0.2917");
  std::smatch divider;
  ASSERT_TRUE(std::regex_search(dom, divider, std::regex("class=\"divider\" style=\"([^\"]*)\"")));
  EXPECT_EQ(divider[1], "left: 29.17%;");
  EXPECT_LT(seconds, 60.0);
}

TEST(ReportChromium, TickedCasesAndAReasonMakeOneBlessCommand) {
  const std::string chromium = findChromium();
  if (chromium.empty())
    GTEST_SKIP() << "chromium not found (apt-get install chromium, or set TAA_CHROMIUM)";
  const fs::path dir = fs::absolute(taa::test::freshDir("chromium_bless"));
  auto results = taa::test::sampleRun(dir);
  // Besides moving_fence (failing): a stale case whose file needs quoting, and a failing one.
  auto stale = results.cases[1];
  stale.name = "fence_thin";
  stale.file = "cases/fence thin.json";
  stale.status = taa::run::CaseStatus::Stale;
  auto other = results.cases[1];
  other.name = "tonemap";
  other.file = "cases/tonemap.json";
  results.cases.push_back(stale);
  results.cases.push_back(other);
  taa::report::writeHtmlReport(dir / "report.html", results);

  // A report downloaded from CI: the folder is edited to where the artifact was unpacked.
  const std::string reason = "fence's new blend weight (issue 47)";
  const std::string url =
      "file://" + taa::report::encodePath((dir / "report.html").string()) +
      "#bless-tick=moving_fence,fence_thin&bless-dir=ci%20artifact/taa-shard-1"
      "&bless-reason=fence%27s%20new%20blend%20weight%20(issue%2047)&bless-all=1";
  const std::string dom = dumpDom(chromium, dir / "profile", url, dir / "chromium.log");
  ASSERT_NE(dom.find("</html>"), std::string::npos)
      << "no DOM from chromium; see " << (dir / "chromium.log");
  auto body = bodyAttributes(dom);
  EXPECT_EQ(body.count("data-js-error"), 0u) << body["data-js-error"];
  EXPECT_EQ(body["data-render-ok"], "1");
  EXPECT_EQ(body["data-bless-before-reason"], "hint: No command yet: type a reason.");
  // Before the folder is edited: the one the page was opened from.
  EXPECT_EQ(body["data-bless-here"],
            "taa-harness bless --from " + dir.string() +
                " cases/moving_fence.json 'cases/fence thin.json' --reason 'fence'\\''s new blend "
                "weight (issue 47)'");
  const std::string command = body["data-bless-command"];
  EXPECT_EQ(command,
            "taa-harness bless --from 'ci artifact/taa-shard-1' cases/moving_fence.json "
            "'cases/fence thin.json' --reason 'fence'\\''s new blend weight (issue 47)'");
  // What a shell makes of it: the same words, the reason intact.
  const fs::path script = dir / "words.sh";
  {
    std::ofstream out(script);
    out << "set -- " << command << "\nprintf '%s\\n' \"$@\"\n";
  }
  EXPECT_EQ(run("sh '" + script.string() + "'"),
            "taa-harness\nbless\n--from\nci artifact/taa-shard-1\ncases/moving_fence.json\n"
            "cases/fence thin.json\n--reason\n" +
                reason + "\n");
  // Select-all takes every failing or stale case in page order; clearing it hides the command.
  EXPECT_EQ(body["data-bless-all"],
            "taa-harness bless --from 'ci artifact/taa-shard-1' cases/moving_fence.json "
            "'cases/fence thin.json' cases/tonemap.json --reason 'fence'\\''s new blend weight "
            "(issue 47)'");
  EXPECT_EQ(body["data-bless-none"], "hint: No command yet: tick at least one case.");
}

}  // namespace

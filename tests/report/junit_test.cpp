#include "report/junit.h"

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "report/fixture.h"
#include "support/text.h"

namespace {

using taa::test::count;

// Enough of XML 1.0 to catch what a careless writer breaks: nesting, quoted attributes, entities
// and characters that need escaping. Returns an empty string when well-formed, else the problem.
std::string xmlProblem(const std::string& xml) {
  std::vector<std::string> open;
  const std::regex entity("&(amp|lt|gt|quot|apos|#[0-9]+|#x[0-9a-fA-F]+);");
  const std::regex tag(R"(^<(/?)([A-Za-z_][\w.-]*)((?:\s+[\w.-]+="[^"<]*")*)\s*(/?)>)");
  auto checkText = [&](const std::string& text) -> std::string {
    if (text.find('>') != std::string::npos) return "'>' in text";
    for (size_t a = text.find('&'); a != std::string::npos; a = text.find('&', a + 1))
      if (!std::regex_search(text.begin() + long(a), text.end(), entity,
                             std::regex_constants::match_continuous))
        return "bare '&' in: " + text.substr(a, 20);
    return "";
  };
  size_t pos = 0;
  if (xml.rfind("<?xml ", 0) == 0) pos = xml.find("?>") + 2;
  bool rootSeen = false;
  while (pos < xml.size()) {
    const size_t lt = xml.find('<', pos);
    const std::string text =
        xml.substr(pos, lt == std::string::npos ? std::string::npos : lt - pos);
    if (auto p = checkText(text); !p.empty()) return p;
    if (open.empty() && text.find_first_not_of(" \n") != std::string::npos) return "text at root";
    if (lt == std::string::npos) break;
    std::smatch m;
    const std::string rest = xml.substr(lt, 4000);
    if (!std::regex_search(rest, m, tag)) return "bad tag at " + rest.substr(0, 40);
    if (auto p = checkText(m[3]); !p.empty()) return "attribute: " + p;
    if (m[1] == "/") {
      if (open.empty() || open.back() != m[2]) return "unbalanced </" + m[2].str() + ">";
      open.pop_back();
    } else {
      if (open.empty() && rootSeen) return "second root element";
      rootSeen = true;
      if (m[4] != "/") open.push_back(m[2]);
    }
    pos = lt + size_t(m.length(0));
  }
  return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

TEST(ReportJUnit, OneTestcasePerCaseWithFailuresErrorsAndSkips) {
  const auto dir = taa::test::freshDir("junit");
  auto results = taa::test::sampleRun(dir);
  results.cases[1].name = "moving_fence \"<&>\"";
  taa::report::writeJUnit(dir / "junit.xml", results);
  std::ifstream in(dir / "junit.xml");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string xml = ss.str();

  EXPECT_EQ(xmlProblem(xml), "");
  EXPECT_EQ(count(xml, "<testsuite "), 1u);
  EXPECT_EQ(count(xml, "<testcase "), 4u);
  EXPECT_EQ(count(xml, "<failure "), 1u);
  EXPECT_EQ(count(xml, "<error "), 1u);
  EXPECT_EQ(count(xml, "<skipped "), 1u);
  EXPECT_NE(xml.find("tests=\"4\" failures=\"1\" errors=\"1\" skipped=\"1\" time=\"3.750\""),
            std::string::npos);
  EXPECT_NE(xml.find("<testcase classname=\"taa\" name=\"static_sponza\""), std::string::npos);
  EXPECT_NE(xml.find("name=\"moving_fence &quot;&lt;&amp;&gt;&quot;\""), std::string::npos);
  // Golden-frame failures and failed invariants, one per line; passed invariants stay out.
  EXPECT_NE(xml.find("frame 8: rmse 0.021 &gt; 0.01\nframe 8: flip_mean 0.08 &gt; 0.05\n"
                     "frame 8: flip_p99 nan &gt; 0.2\n"
                     "invariant ghosting_decay: residual 0.12 &gt; 0.05"),
            std::string::npos);
  EXPECT_EQ(xml.find("no_nan"), std::string::npos);
  EXPECT_NE(xml.find("&quot;&lt;bin&gt;&quot;"), std::string::npos);
  EXPECT_EQ(xml, taa::report::renderJUnit(results));
}

TEST(ReportJUnit, ControlCharactersAndStaleCases) {
  taa::run::RunResults r;
  taa::run::CaseResult c;
  c.name = "stale\x01one";
  c.status = taa::run::CaseStatus::Stale;
  c.message = "case file changed since the golden was blessed";
  r.cases = {c};
  const std::string xml = taa::report::renderJUnit(r);
  EXPECT_EQ(xmlProblem(xml), "");
  EXPECT_EQ(xml.find('\x01'), std::string::npos);
  EXPECT_NE(xml.find("<failure type=\"stale\" message=\"case file changed"), std::string::npos);
  EXPECT_NE(xmlProblem("<a><b></a></b>"), "");  // the checker itself catches breakage
  EXPECT_NE(xmlProblem("<a>x & y</a>"), "");
}

}  // namespace

// The scorecard's plot tells lanes apart by colour alone: a user scoring eight resolves must
// get eight lines that differ, or two lanes read as one.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "score/score.h"
#include "support/text.h"

namespace taa::score_write_test {

namespace fs = std::filesystem;

score::Scorecard scorecardOfLanes(int lanes) {
  score::Scorecard s;
  s.device = "test device";
  for (int lane = 0; lane < lanes; ++lane)
  {
    score::LaneSpec l;
    l.name = lane ? "lane" + std::to_string(lane) : "default";
    s.lanes.push_back(l);
  }
  for (int c = 0; c < 2; ++c) {
    score::CaseScore cs;
    cs.name = "case" + std::to_string(c);
    cs.frames = 4;
    for (int lane = 0; lane < lanes; ++lane) {
      score::LaneScore l;
      l.lane = s.lanes[size_t(lane)].name;
      l.flip = 0.01 * (lane + 1) + 0.001 * c;
      l.flipPerFrame = {l.flip, l.flip, l.flip, l.flip};
      cs.lanes.push_back(l);
    }
    s.cases.push_back(cs);
  }
  return s;
}

// The plot marks each case's FLIP with a dot in its lane's colour.
std::vector<std::string> markerColours(const std::string& svg) {
  static const std::regex line("<circle [^>]*fill=\"([^\"]+)\"");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), line); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

TEST(ScoreWrite, EightLanesAreDrawnInEightColours) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "score-write";
  fs::remove_all(dir);
  score::writeScorecard(dir, scorecardOfLanes(8));
  const std::vector<std::string> colours = markerColours(test::readFile(dir / "score.svg"));
  ASSERT_EQ(colours.size(), 24u) << "two cases' dots and a legend dot per lane";
  EXPECT_EQ(std::set<std::string>(colours.begin(), colours.end()).size(), 8u)
      << "two lanes share a colour";
}

}  // namespace taa::score_write_test

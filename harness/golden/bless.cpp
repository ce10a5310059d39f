#include "golden/bless.h"

#include <array>
#include <cstdio>
#include <ctime>
#include <stdexcept>

#include "core/image_io.h"
#include "golden/case_owner.h"

namespace taa::golden {

namespace {

std::string runCommand(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  std::array<char, 256> buf;
  while (fgets(buf.data(), int(buf.size()), pipe)) out += buf.data();
  if (pclose(pipe) != 0) return "";
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

}  // namespace

std::string todayUtc() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[16];
  std::strftime(buf, sizeof(buf), "%Y-%m-%d", &utc);
  return buf;
}

std::string rendererCommit() {
  const std::string dir = TAA_SOURCE_DIR;
  const std::string head = runCommand("git -C '" + dir + "' rev-parse HEAD 2>/dev/null");
  if (head.empty()) return "unknown";
  const std::string dirty = runCommand("git -C '" + dir + "' status --porcelain --untracked-files=no 2>/dev/null");
  return dirty.empty() ? head : head + "-dirty";
}

Manifest makeManifest(const cases::LoadedCase& loaded, const Environment& env,
                      const std::map<int, Image>& frames, const FrameDigests& digests,
                      const std::string& reason, const Manifest* previous) {
  const auto& sequence = digests.sha256;
  Manifest m;
  m.caseName = loaded.spec.name;
  m.caseSha256 = loaded.sha256;
  m.caseFile = caseFileLabel(loaded.spec.file);
  m.environment = env;
  m.bless = {todayUtc(), rendererCommit(), reason};
  if (previous) {
    m.history.push_back(previous->bless);
    m.history.insert(m.history.end(), previous->history.begin(), previous->history.end());
  }
  m.sequence = sequence;
  m.signatures = digests.signatures;
  for (const auto& [frame, image] : frames) {
    m.frames.push_back({frame, frameBase(frame) + ".exr", pixelSha256(image), image.width, image.height});
    if (size_t(frame) >= sequence.size() || sequence[size_t(frame)] != m.frames.back().sha256)
      throw std::logic_error("bless: frame " + std::to_string(frame) + " of " + m.caseName +
                             " hashes differently from the sequence rendered with it");
  }
  return m;
}

}  // namespace taa::golden

#include "golden/case_owner.h"

namespace taa::golden {

namespace fs = std::filesystem;

std::string caseFileLabel(const fs::path& caseFile) {
  const fs::path file = fs::absolute(caseFile).lexically_normal();
  const std::string folder = file.parent_path().filename().string();
  return folder.empty() ? file.filename().string() : folder + "/" + file.filename().string();
}

bool validCaseFileLabel(const std::string& label) {
  if (label.empty() || label.size() > 512 || label.find('\0') != std::string::npos) return false;
  const auto part = [](const std::string& p) { return !p.empty() && p != "." && p != ".."; };
  const size_t slash = label.find('/');
  if (slash == std::string::npos) return part(label);
  const std::string folder = label.substr(0, slash), file = label.substr(slash + 1);
  return part(folder) && part(file) && file.find('/') == std::string::npos;
}

std::string otherCaseProblem(const Manifest& m, const fs::path& root, const fs::path& caseFile) {
  if (m.caseFile.empty() || m.caseFile == caseFileLabel(caseFile)) return "";
  // Only goldens beside the case's own folder can be a sibling's by accident; a folder given
  // elsewhere (--goldens, another checkout's goldens) was chosen for this case.
  const fs::path base = fs::absolute(root).lexically_normal().parent_path();
  if (fs::absolute(caseFile).lexically_normal().parent_path().parent_path() != base) return "";
  const fs::path owner = base / m.caseFile;
  std::error_code ec;
  if (!fs::is_regular_file(owner, ec) || fs::equivalent(owner, caseFile, ec)) return "";
  return (root / m.caseName).string() + " holds the goldens of " + owner.string() +
         ", which exists beside this case: two case files named '" + m.caseName +
         ".json' share one goldens folder (it is named after the file); rename one of them";
}

}  // namespace taa::golden

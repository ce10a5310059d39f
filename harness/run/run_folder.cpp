#include "run/run_folder.h"

#include <nlohmann/json.hpp>

#include "core/contained_file.h"
#include "core/json_guard.h"
#include "golden/manifest.h"
#include "run/results_visitors.h"

namespace taa::run {

namespace fs = std::filesystem;

namespace {

// One suffix per FrameFile, in its order.
const char* suffixOf(FrameFile kind) {
  switch (kind) {
    case FrameFile::Exr: return ".exr";
    case FrameFile::Png: return ".png";
    case FrameFile::GoldenPng: return ".golden.png";
    case FrameFile::DiffPng: return ".diff.png";
    case FrameFile::ZoomActualPng: return ".zoom_actual.png";
    case FrameFile::ZoomGoldenPng: return ".zoom_golden.png";
    case FrameFile::ZoomDiffPng: return ".zoom_diff.png";
    case FrameFile::AbPng: return ".ab.png";
    case FrameFile::ZoomAbPng: return ".zoom_ab.png";
    case FrameFile::ReferenceExr: return ".reference.exr";
    case FrameFile::ReferencePng: return ".reference.png";
  }
  return ".unknown";
}

}  // namespace

std::string frameFileName(int frame, FrameFile kind) {
  return golden::frameBase(frame) + suffixOf(kind);
}

std::string frameCaptureName(int frame, const std::string& capture) {
  return golden::frameBase(frame) + "." + capture + ".exr";
}

RunFolder::RunFolder(fs::path root) : root_(std::move(root)) {}

RunFolder RunFolder::ofResultsFile(const fs::path& results) {
  RunFolder f(results.parent_path());
  f.resultsName_ = results.filename();
  return f;
}

std::string RunFolder::caseFile(const std::string& name, int frame, FrameFile kind) {
  return name + "/" + frameFileName(frame, kind);
}

std::string RunFolder::readResultsText(const std::string& fix) const {
  try {
    return readContainedFile(root_, resultsName_, kMaxResultsFileBytes, "the results file");
  } catch (const InputFileError& e) {
    throw RunFolderError(std::string(e.what()) + "; " + fix);
  }
}

RunResults RunFolder::parseResults(const std::string& text, const std::string& fix) const {
  const std::string file = resultsFile().string();
  if (const std::string problem = jsonStructureProblem(text); !problem.empty())
    throw RunFolderError(file + ": " + problem);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw RunFolderError(file + ": not the results.json of a run (" +
                         jsonErrorWithoutContent(e.what()) + "); " + fix);
  }
  try {
    return runResultsFromJson(j);
  } catch (const ResultsFormatError& e) {
    throw RunFolderError(file + ": " + e.what() + "; " + fix);
  }
}

RunResults RunFolder::readResults(const std::string& fix) const {
  return parseResults(readResultsText(fix), fix);
}

void RunFolder::checkFile(const fs::path& relative, const std::string& what,
                          const std::string& fix) const {
  try {
    checkContainedFile(root_, relative, kMaxRunImageBytes, what);
  } catch (const InputFileError& e) {
    throw RunFolderError(std::string(e.what()) + "; " + fix);
  }
}

std::string RunFolder::readFile(const fs::path& relative, const std::string& what,
                                const std::string& fix) const {
  try {
    return readContainedFile(root_, relative, kMaxRunImageBytes, what);
  } catch (const InputFileError& e) {
    throw RunFolderError(std::string(e.what()) + "; " + fix);
  }
}

}  // namespace taa::run

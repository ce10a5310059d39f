// A run's output folder, the one owner of its layout: every file name in it (results, JUnit,
// report, each case's frame images and EXRs, the staging folder of `run -j`) and the one way
// another command reads it back (`merge`, `coverage --results`, `run --verdict-from`,
// `bless --from`, `bless --failed-from`). `run`, `render` and `bless` write through the names
// it gives; every read goes through core/contained_file.h's input-path rule (inside the folder
// once links are resolved, a regular file, bounded), as the folder may come from another
// machine.
//
// OUT/results.json, OUT/results.json.seal (run/results_seal.h), OUT/junit.xml, OUT/report.html
// OUT/NAME/frame_NNNN.<kind>   a case's frame files, kinds in FrameFile
// OUT/.taa-harness-in-progress/NAME/   where a worker writes a case until its turn (run -j)
#pragma once

#include <filesystem>
#include <string>

#include "core/errors.h"
#include "run/results.h"

namespace taa::run {

// A run folder (or a file in it) that cannot be read as one: names the file, what is wrong and
// the fix. Printed as the command's own argument error, as the folder is its argument.
class RunFolderError : public InputError {
 public:
  using InputError::InputError;
  std::string report(const std::string& command) const override {
    return "taa-harness " + command + ": " + what();
  }
};

// The files a run, render or bless writes for one frame of a case, beside frame_NNNN.
enum class FrameFile {
  Exr,             // the output, linear half float
  Png,             // the output, tonemapped sRGB
  GoldenPng,       // the golden frame compared with
  DiffPng,         // heatmap of the per-pixel error
  ZoomActualPng,   // the magnified region of the output
  ZoomGoldenPng,   // of the golden
  ZoomDiffPng,     // of the heatmap
  AbPng,           // report.ab's B side
  ZoomAbPng,       // and its magnified region
  ReferenceExr,    // render --reference: the supersampled ground truth
  ReferencePng,
};

// "frame_0012.golden.png": the one spelling of a frame file's name (golden::frameBase + kind).
std::string frameFileName(int frame, FrameFile kind);
// "frame_0012.velocity.exr": a capture (api/captures.h) render writes by its name.
std::string frameCaptureName(int frame, const std::string& capture);

class RunFolder {
 public:
  explicit RunFolder(std::filesystem::path root);
  // The folder of a results file given by path (run --verdict-from, coverage --results), which
  // keeps its own file name.
  static RunFolder ofResultsFile(const std::filesystem::path& results);

  const std::filesystem::path& root() const { return root_; }
  std::filesystem::path resultsFile() const { return root_ / resultsName_; }
  std::filesystem::path junitFile() const { return root_ / "junit.xml"; }
  std::filesystem::path reportFile() const { return root_ / "report.html"; }
  std::filesystem::path stagingFolder() const { return root_ / ".taa-harness-in-progress"; }
  std::filesystem::path caseFolder(const std::string& name) const { return root_ / name; }
  // NAME/frame_NNNN.<kind>, relative to the folder: how results.json and the report name it.
  static std::string caseFile(const std::string& name, int frame, FrameFile kind);

  // results.json's bytes, read under the input-path rule (for a reader that checks the seal
  // before it parses), and their parse; RunFolderError naming the file, with `fix` appended.
  std::string readResultsText(const std::string& fix) const;
  RunResults parseResults(const std::string& text, const std::string& fix) const;
  RunResults readResults(const std::string& fix) const;
  // A file of a case's folder the results name (`relative` to the folder), under the same rule;
  // `what` names it in the refusal. checkFile only checks, readFile also reads it.
  void checkFile(const std::filesystem::path& relative, const std::string& what,
                 const std::string& fix) const;
  std::string readFile(const std::filesystem::path& relative, const std::string& what,
                       const std::string& fix) const;

 private:
  std::filesystem::path root_;
  std::filesystem::path resultsName_ = "results.json";
};

}  // namespace taa::run

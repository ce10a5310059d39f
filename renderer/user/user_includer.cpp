#include "user/user_includer.h"

#include <system_error>

#include "api/loader_errors.h"  // ShaderCompileError
#include "core/input_file.h"
#include "user/shader_bounds.h"

namespace taa::user {

namespace fs = std::filesystem;

namespace {

fs::path absoluteNormal(const fs::path& p) {
  std::error_code ec;
  return fs::absolute(p, ec).lexically_normal();
}

}  // namespace

UserIncluder::UserIncluder(fs::path root, fs::path headerDir)
    : root_(std::move(root)), headerDir_(std::move(headerDir)) {}

UserIncluder::IncludeResult* UserIncluder::includeLocal(const char* header, const char* includer,
                                                        size_t depth) {
  return resolve(header, includer, depth, true);
}

UserIncluder::IncludeResult* UserIncluder::includeSystem(const char* header, const char* includer,
                                                         size_t depth) {
  return resolve(header, includer, depth, false);
}

void UserIncluder::releaseInclude(IncludeResult* r) {
  if (r) delete static_cast<std::string*>(r->userData);
  delete r;
}

UserIncluder::IncludeResult* UserIncluder::resolve(const char* header, const char* includer,
                                                   size_t depth, bool local) {
  if (stopped_) return nullptr;  // a bound was reached: glslang's error recovery asks on
  if (depth > kMaxIncludeDepth)
    return stop(std::string(includer) + ": includes nest deeper than " +
                std::to_string(kMaxIncludeDepth) +
                " (a header including itself?); break the cycle");
  if (++count_ > kMaxIncludes)
    return stop(std::string(includer) + ": resolves more than " + std::to_string(kMaxIncludes) +
                " #include directives, counting repeats (a header including itself twice?); "
                "guard the header or include it fewer times");
  std::vector<fs::path> candidates;
  if (local) candidates.push_back(fs::path(includer).parent_path() / header);
  if (!headerDir_.empty()) candidates.push_back(headerDir_ / header);
  const std::string what = std::string(includer) + ": #include \"" + header + "\"";
  // Whether a path outside the folders exists is not the shader's business: the text of the
  // path decides first, then its real path; both refusals read the same.
  const std::string leaves = what +
                             " leads outside the shader's folder; move the header under "
                             "that folder";
  std::error_code ec;
  for (const auto& c : candidates) {
    const fs::path lexical = absoluteNormal(c);
    if (!allowed(lexical)) return stop(leaves);
    if (!fs::exists(fs::symlink_status(lexical, ec))) continue;
    const fs::path real = followLinks(lexical);
    if (real.empty() || !allowed(real)) return stop(leaves);
    if (!fs::exists(real, ec)) continue;
    std::string text;
    try {
      text = readShaderText(real, what);
    } catch (const ShaderCompileError& e) {
      return stop(e.what());
    }
    bytes_ += text.size();
    if (bytes_ > kMaxIncludedBytes)
      return stop(what + ": the headers read add up to more than " +
                  std::to_string(kMaxIncludedBytes >> 20) + " MiB, counting repeats");
    auto* kept = new std::string(std::move(text));
    files_.push_back(real);
    return new IncludeResult(real.string(), kept->data(), kept->size(), kept);
  }
  // glslang asks the system paths after a failed local lookup: keep the first, sharper reason.
  if (!problem_.empty()) return nullptr;
  problem_ = what + " not found beside it" +
             (headerDir_.empty() ? "" : " nor in the installed headers") +
             "; check the name, or put the header in the shader's folder";
  return nullptr;
}

UserIncluder::IncludeResult* UserIncluder::stop(const std::string& why) {
  if (problem_.empty() || !stopped_) problem_ = why;
  stopped_ = true;
  return nullptr;
}

bool UserIncluder::allowed(const fs::path& p) {
  return isInsideFolder(absoluteNormal(root_), p) || isInsideFolder(rootReal(), p) ||
         (!headerDir_.empty() && isInsideFolder(absoluteNormal(headerDir_), p)) ||
         isInsideFolder(headerReal(), p);
}

const fs::path& UserIncluder::rootReal() {
  if (rootReal_.empty()) {
    std::error_code ec;
    rootReal_ = fs::canonical(root_, ec);
  }
  return rootReal_;
}

const fs::path& UserIncluder::headerReal() {
  if (headerReal_.empty() && !headerDir_.empty()) {
    std::error_code ec;
    headerReal_ = fs::canonical(headerDir_, ec);
  }
  return headerReal_;
}

}  // namespace taa::user

#include "user/spirv_cache.h"

#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/cache_folder.h"
#include "core/input_file.h"
#include "core/output_file.h"
#include "core/sha256.h"
#include "user/shader_bounds.h"

namespace taa::user {

namespace fs = std::filesystem;

namespace {

std::string fileSha(const fs::path& file) {
  const std::string bytes = readShaderText(file, file.string());
  return sha256Hex(bytes.data(), bytes.size());
}

// One of an entry's files as the cache wrote it, through the hardened reader: nullopt when it is
// not there, or (with `foreign` set) when something else is under its name (a FIFO that would
// hang the compile, a device, a link), which is deleted so that the fresh entry takes the name
// (a link goes, not what it points at).
std::optional<std::string> readEntryFile(const fs::path& file, bool& foreign) {
  try {
    return readInputFile(file, kMaxShaderFileBytes * 16, LastLink::Refuse);
  } catch (const InputFileMissing&) {
    return std::nullopt;
  } catch (const InputFileError&) {
    std::error_code ec;
    fs::remove(file, ec);
    foreign = true;
    return std::nullopt;
  }
}

void writeEntry(const fs::path& dir, const std::string& key, const CompiledShader& c) {
  createOutputDirectory(dir);
  const std::string_view bytes(reinterpret_cast<const char*>(c.spirv.data()), c.spirv.size() * 4);
  // Words first: a deps file never names SPIR-V that is not there.
  writeFileAtomically(dir / (key + ".spv"), bytes);
  std::string deps = "spv " + sha256Hex(bytes.data(), bytes.size()) + "\n";
  for (const auto& inc : c.includes) deps += "inc " + fileSha(inc) + " " + inc.string() + "\n";
  for (const auto& cap : c.capabilities) deps += "cap " + cap + "\n";
  for (const auto& con : c.constants)
    deps += std::string("con ") + paramTypeName(con.type) + " " + std::to_string(con.id) + " " +
            con.name + "\n";
  writeFileAtomically(dir / (key + ".deps"), deps);
}

}  // namespace

bool readSpirvCache(const fs::path& dir, const std::string& key, CompiledShader& out,
                    std::string& why) {
  if (dir.empty()) return false;
  bool foreign = false;
  const std::optional<std::string> depsText = readEntryFile(dir / (key + ".deps"), foreign);
  if (!depsText) {
    if (foreign) why = "the cache entry was not a file the cache wrote";
    return false;
  }
  std::istringstream deps(*depsText);
  why = "the cache entry was damaged";
  std::string kind, sha, spvSha;
  std::vector<fs::path> includes;
  std::vector<std::string> capabilities;
  std::vector<DeclaredConstant> constants;
  std::string line;
  while (std::getline(deps, line)) {
    std::istringstream l(line);
    l >> kind >> sha;
    std::string path;
    std::getline(l >> std::ws, path);
    if (kind == "spv") {
      spvSha = sha;
    } else if (kind == "cap") {
      capabilities.push_back(sha);
    } else if (kind == "con") {  // "con TYPE ID NAME": the id as declaredConstants read it
      const auto type = paramTypeNamed(sha);
      std::istringstream rest(path);
      int64_t id = 0;
      std::string name, extra;
      if (!type || !(rest >> id >> name) || id < -1 || id > kConstantIdCap) return false;
      if (rest >> extra) return false;  // our writer puts nothing after the name
      constants.push_back({name, *type, id});
    } else if (kind == "inc") {
      std::error_code ec;
      if (!fs::is_regular_file(path, ec)) {
        why = path + " is gone since it was cached";
        return false;
      }
      try {
        if (fileSha(path) != sha) {
          why = path + " changed since it was cached";
          return false;
        }
      } catch (const ShaderCompileError&) {
        why = path + " cannot be read";
        return false;
      }
      includes.emplace_back(path);
    } else {
      return false;
    }
  }
  if (spvSha.empty()) return false;
  const std::optional<std::string> words = readEntryFile(dir / (key + ".spv"), foreign);
  if (!words) return false;
  const std::string& bytes = *words;
  if (bytes.size() % 4 != 0 || sha256Hex(bytes.data(), bytes.size()) != spvSha) return false;
  out.spirv.resize(bytes.size() / 4);
  std::memcpy(out.spirv.data(), bytes.data(), bytes.size());
  out.includes = std::move(includes);
  out.capabilities = std::move(capabilities);
  out.constants = std::move(constants);
  out.fromCache = true;
  return true;
}

std::string writeSpirvCache(const fs::path& dir, const std::string& key, const CompiledShader& c) {
  if (dir.empty()) return "no cache folder (set TAA_SHADER_CACHE, XDG_CACHE_HOME or HOME)";
  try {
    writeEntry(dir, key, c);
  } catch (const std::runtime_error& e) {  // the folder, an entry's name, an include gone since
    return e.what();
  }
  return "";
}

fs::path userShaderCacheDir() {
  if (const char* env = std::getenv("TAA_SHADER_CACHE"); env && *env) return env;
  // No shared fallback such as /tmp: another user could put SPIR-V there under a key we ask
  // for. Without a folder of the user's own, shaders compile every time.
  return userCacheFolder("spirv");
}

}  // namespace taa::user

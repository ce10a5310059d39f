#include "user/spirv_cache.h"

#include <cstdlib>
#include <cstring>
#include <sstream>

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

}  // namespace

bool readSpirvCache(const fs::path& dir, const std::string& key, CompiledShader& out, std::string& why) {
  if (dir.empty()) return false;
  std::string depsText;
  try {
    // The hardened reader: a FIFO or device under the entry's name would otherwise hang the
    // compile or feed it without end; a link is not an entry this cache wrote.
    depsText = readInputFile(dir / (key + ".deps"), kMaxShaderFileBytes * 16, LastLink::Refuse);
  } catch (const InputFileMissing&) {
    return false;
  } catch (const InputFileError&) {
    // Dropped, as a damaged entry is rewritten: the compile's fresh entry takes the name.
    std::error_code ec;
    fs::remove(dir / (key + ".deps"), ec);  // a link goes, not what it points at
    why = "the cache entry was not a file the cache wrote";
    return false;
  }
  std::istringstream deps(depsText);
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
  std::string bytes;
  try {
    bytes = readInputFile(dir / (key + ".spv"), kMaxShaderFileBytes * 16, LastLink::Refuse);
  } catch (const InputFileMissing&) {
    return false;
  } catch (const InputFileError&) {
    std::error_code ec;
    fs::remove(dir / (key + ".spv"), ec);
    return false;
  }
  if (bytes.size() % 4 != 0 || sha256Hex(bytes.data(), bytes.size()) != spvSha) return false;
  out.spirv.resize(bytes.size() / 4);
  std::memcpy(out.spirv.data(), bytes.data(), bytes.size());
  out.includes = std::move(includes);
  out.capabilities = std::move(capabilities);
  out.constants = std::move(constants);
  out.fromCache = true;
  return true;
}

void writeSpirvCache(const fs::path& dir, const std::string& key, const CompiledShader& c) {
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

fs::path userShaderCacheDir() {
  if (const char* env = std::getenv("TAA_SHADER_CACHE"); env && *env) return env;
  // No shared fallback such as /tmp: another user could put SPIR-V there under a key we ask
  // for. Without a folder of the user's own, shaders compile every time.
  return userCacheFolder("spirv");
}

}  // namespace taa::user

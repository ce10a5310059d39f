#include "user/user_resolve.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <set>
#include <stdexcept>

#include "core/closest_match.h"
#include "passes/storage_image.h"
#include "script/timing.h"
#include "user/glsl_compiler.h"
#include "user/user_uniforms.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

namespace {

// taa_user.h's TaaUserFrame (common/user_frame.h), std140: matrices and vectors of four
// 4-byte components only, so every member starts where the previous one ends.
using UserCxx_mat4 = glm::mat4;
using UserCxx_vec4 = glm::vec4;
using UserCxx_uvec4 = glm::uvec4;
#define TAA_USER_CXX_MEMBER(type, name, doc) UserCxx_##type name;
struct UserFrameUniforms {
  TAA_USER_FRAME(TAA_USER_CXX_MEMBER)
};
#undef TAA_USER_CXX_MEMBER
#define TAA_USER_CXX_ALIGNED(type, name, doc)                                    \
  static_assert(sizeof(UserCxx_##type) % 16 == 0 && offsetof(UserFrameUniforms, name) % 16 == 0, \
                "TaaUserFrame." #name " would be padded in std140");
TAA_USER_FRAME(TAA_USER_CXX_ALIGNED)
#undef TAA_USER_CXX_ALIGNED

// An output-size target the shader writes and later samples, zeroed once so that a shader
// reading it on a reset frame sees zeros rather than another run's memory.
vk::Image userTarget(vk::Context& ctx, const char* name, glm::ivec2 size, VkFormat format) {
  return zeroedImage(ctx, storageImageDesc(name, size, format), vk::Use::SampledCompute);
}

const char* userFormatName(VkFormat f) {
  switch (f) {
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return "rgba32f";
    case VK_FORMAT_R16G16B16A16_SFLOAT:
      return "rgba16f";
    case VK_FORMAT_R32G32_SFLOAT:
      return "rg32f";
    case VK_FORMAT_R16G16_SFLOAT:
      return "rg16f";
    case VK_FORMAT_R32_SFLOAT:
      return "r32f";
    case VK_FORMAT_R16_SFLOAT:
      return "r16f";
    default:
      return "?";
  }
}

// The 32 bits a specialization constant of type `t` takes for `v`, or an error message.
std::string userParamBits(user::ParamType t, const spec::NumberOrBool& v, uint32_t& bits) {
  if (!v.list.empty())
    return std::string("a specialization constant takes one value, not a list; give a ") +
           user::paramTypeName(t);
  return user::scalarBits(t, v, bits);
}

// The value a constant's 32 bits stand for, as a case would write it.
spec::NumberOrBool userParamValue(user::ParamType t, uint32_t bits) {
  switch (t) {
    case user::ParamType::Bool:
      return {bits ? 1.0 : 0.0, true, {}};
    case user::ParamType::Int:
      return {double(int32_t(bits)), false, {}};
    case user::ParamType::Uint:
      return {double(bits), false, {}};
    case user::ParamType::Float: {
      float f = 0.0f;
      std::memcpy(&f, &bits, 4);
      // The shortest decimal that reads back as the same float (0.1, not 0.100000001).
      char buf[32];
      const auto r = std::to_chars(buf, buf + sizeof(buf), f);
      return {std::strtod(std::string(buf, r.ptr).c_str(), nullptr), false, {}};
    }
  }
  return {};
}

glm::ivec2 userOutputSize(const spec::CaseSpec& s) {
  return {s.render.width, s.render.height};
}

}  // namespace

user::ShaderLanguage userShaderLanguage(const spec::TaaSpec& taa) {
  switch (taa.shader_language) {
    case spec::ShaderLanguage::Glsl:
      return user::ShaderLanguage::Glsl;
    case spec::ShaderLanguage::Hlsl:
      return user::ShaderLanguage::Hlsl;
    case spec::ShaderLanguage::Auto:
      break;
  }
  return user::languageOf(taa.shader);
}

UserShader loadUserShader(const spec::CaseSpec& spec) {
  const std::filesystem::path caseDir =
      spec.file.parent_path().empty() ? std::filesystem::path(".") : spec.file.parent_path();
  UserShader out;
  out.root = spec.taa.shader_root.empty() ? caseDir : std::filesystem::path(spec.taa.shader_root);
  out.file = out.root / spec.taa.shader;
  out.language = userShaderLanguage(spec.taa);
  user::CompileOptions o;
  o.root = out.root;
  o.language = out.language;
  o.entry = spec.taa.shader_entry;
  o.defines = spec.taa.shader_defines;
  user::CompiledShader c = user::compileComputeShader(out.file, o);
  try {
    out.interface = user::reflectUserInterface(c.spirv, out.file.string());
    user::noteUnreadConstants(out.interface, c.constants);
  } catch (const InputError& e) {  // the shader breaks taa_user.h's contract
    throw user::ShaderCompileError(std::string(e.what()) + " (see docs/user-taa.md)");
  }
  out.spirv = std::move(c.spirv);
  out.includes = std::move(c.includes);
  out.capabilities = std::move(c.capabilities);
  out.provenance = std::move(c.provenance);
  return out;
}

std::vector<std::string> userParamProblems(const spec::TaaSpec& taa, const user::UserInterface& u) {
  std::vector<std::string> out;
  std::string declared;
  std::vector<std::string> names;
  for (const auto& p : u.params) {
    declared += (declared.empty() ? "" : ", ") + p.name + " (" + user::paramTypeName(p.type) + ")";
    names.push_back(p.name);
  }
  for (const auto& c : u.unread) {
    declared += (declared.empty() ? "" : ", ") + c.name + " (" + user::paramTypeName(c.type) +
                ", not read by its code)";
    names.push_back(c.name);
  }
  for (const auto& m : u.uniforms) {
    declared += (declared.empty() ? "" : ", ") + m.name + " (" + m.typeName() + " uniform)";
    names.push_back(m.name);
  }
  if (declared.empty()) declared = "none";
  // Each repeat is named once, not once per earlier copy: a list of thousands stays linear.
  std::set<std::string> seen;
  for (size_t i = 0; i < taa.shader_params.size(); ++i) {
    const auto& sp = taa.shader_params[i];
    const std::string key = "taa.shader_params[" + std::to_string(i) + "]";
    const user::UserParam* p = u.param(sp.name);
    const user::UserUniform* uniform = p ? nullptr : u.uniform(sp.name);
    const user::DeclaredConstant* unread = p || uniform ? nullptr : u.unreadParam(sp.name);
    if (!p && !unread && !uniform) {
      const std::string guess = closestMatch(sp.name, names);
      // Both kinds are set here; naming only constants misled a port that set a uniform.
      out.push_back(key + ".name: '" + sp.name +
                    "' is not a specialization constant or loose uniform of " + taa.shader +
                    (guess.empty() ? "" : "; did you mean '" + guess + "'?") +
                    "; it declares: " + declared);
      continue;
    }
    if (!seen.insert(sp.name).second)
      out.push_back(key + ".name: '" + sp.name + "' is set twice; remove one");
    if (uniform) {
      if (const std::string why = user::uniformValueProblem(*uniform, sp.value); !why.empty())
        out.push_back(key + ".value: " + why);
      continue;
    }
    const user::ParamType type = p ? p->type : unread->type;
    uint32_t bits = 0;
    if (const std::string why = userParamBits(type, sp.value, bits); !why.empty())
      out.push_back(key + ".value: " + sp.name + " is declared " + user::paramTypeName(type) +
                    "; " + why);
  }
  return out;
}

std::map<uint32_t, uint32_t> userSpecValues(const spec::TaaSpec& taa, const user::UserInterface& u) {
  std::map<uint32_t, uint32_t> out;
  for (const auto& sp : taa.shader_params)
    if (const user::UserParam* p = u.param(sp.name)) {
      uint32_t bits = 0;
      if (userParamBits(p->type, sp.value, bits).empty()) out[p->specId] = bits;
    }
  return out;
}

vk::SpecConstants userSpecConstants(const spec::TaaSpec& taa, const user::UserInterface& u) {
  vk::SpecConstants c;
  for (const auto& [id, bits] : userSpecValues(taa, u)) c.set(id, bits);
  return c;
}

std::vector<UserParamValue> userParamValues(const spec::TaaSpec& taa, const user::UserInterface& u) {
  std::vector<UserParamValue> out;
  for (const user::UserParam& p : u.params) {
    UserParamValue v{p.name, p.type, p.defaultBits, false, {}};
    for (const auto& sp : taa.shader_params)
      if (sp.name == p.name && userParamBits(p.type, sp.value, v.bits).empty()) v.given = true;
    v.value = userParamValue(p.type, v.bits);
    out.push_back(v);
  }
  for (const user::DeclaredConstant& c : u.unread)
    for (const auto& sp : taa.shader_params) {
      UserParamValue v{c.name, c.type, 0, true, {}, true};
      if (sp.name != c.name || !userParamBits(c.type, sp.value, v.bits).empty()) continue;
      v.value = userParamValue(c.type, v.bits);
      out.push_back(v);
      break;
    }
  return out;
}

std::vector<std::string> userParamNotes(const std::vector<UserParamValue>& values) {
  std::vector<std::string> out;
  for (const auto& v : values)
    if (v.unread)
      out.push_back("`" + v.name + "` is not read by the shader's code (its compile removed the " +
                    "constant), so taa.shader_params' value for it has no effect");
  return out;
}

std::string describeUserParams(const std::vector<UserParamValue>& values) {
  std::string out;
  for (const auto& v : values) {
    std::string text;
    if (v.value.isBool) {
      text = v.value.number != 0.0 ? "true" : "false";
    } else {
      char buf[32];
      const auto r = std::to_chars(buf, buf + sizeof(buf), v.value.number);
      text.assign(buf, r.ptr);
    }
    out += (out.empty() ? "" : ", ") + v.name + "=" + text + " (" + user::paramTypeName(v.type) +
           (v.unread  ? ", not read"
            : v.given ? ""
                      : ", default") +
           ")";
  }
  return out.empty() ? "none" : out;
}

std::string describeUserDefines(const spec::TaaSpec& taa) {
  std::string out;
  for (const auto& d : taa.shader_defines) out += " -D" + d;
  return out.empty() ? "" : ", defines" + out;
}

namespace {

// Everything shader_params sets: the constants, then the loose uniforms. A port whose values
// are all uniforms read "params: none" beside them before.
std::string describeAllParams(const spec::TaaSpec& taa, const user::UserInterface& u) {
  const auto values = userParamValues(taa, u);
  const std::string uniforms = user::describeUserUniforms(taa, u);
  if (values.empty() && !uniforms.empty()) return uniforms;
  return describeUserParams(values) + (uniforms.empty() ? "" : "; " + uniforms);
}

}  // namespace

std::string describeUserShader(const spec::CaseSpec& spec) {
  if (spec.taa.shader.empty()) return "";
  const UserShader shader = loadUserShader(spec);
  const bool hlsl = shader.language == user::ShaderLanguage::Hlsl;
  return "user shader " + spec.taa.shader + " (" + user::languageName(shader.language) +
         (hlsl ? ", entry " + spec.taa.shader_entry : "") + describeUserDefines(spec.taa) +
         "), params: " + describeAllParams(spec.taa, shader.interface);
}

GBufferNeeds userNeeds(const user::UserInterface& u) {
  return gbufferNeeds(u.reads);
}

struct UserResolvePass::Impl {
  vk::Context& ctx;
  const spec::CaseSpec& spec;
  UserShader shader;
  vk::Pipeline pipeline;
  vk::Image output[2];
  vk::Image history[2][2];  // [target][ping-pong]
  vk::Buffer uniforms;
  vk::Buffer params;  // the loose uniforms, when the shader has any
  vk::Sampler linear, point;
  int current = 0;
  glm::vec2 prevJitter{0.0f};
  glm::ivec2 prevRenderSize{1};

  Impl(vk::Context& c, const spec::CaseSpec& s, UserShader sh)
      : ctx(c),
        spec(s),
        shader(std::move(sh)),
        uniforms(c, sizeof(UserFrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true),
        linear(c, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE),
        point(c, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
    pipeline = vk::createComputePipelineFromSpirv(c, shader.file.filename().string(), shader.spirv,
                                                  userSpecConstants(s.taa, shader.interface));
    if (shader.interface.uniformBytes > 0) {
      // Set once: a case's values hold for the whole run.
      const std::vector<uint8_t> bytes = user::userUniformBytes(s.taa, shader.interface);
      params = vk::Buffer(c, bytes.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
      std::memcpy(params.mapped(), bytes.data(), bytes.size());
    }
    const glm::ivec2 size = userOutputSize(s);
    output[0] = userTarget(c, "user_output_a", size, VK_FORMAT_R16G16B16A16_SFLOAT);
    output[1] = userTarget(c, "user_output_b", size, VK_FORMAT_R16G16B16A16_SFLOAT);
    for (int k = 0; k < 2; ++k)
      if (const auto f = shader.interface.history[k]) {
        history[k][0] = userTarget(c, k ? "user_history1_a" : "user_history0_a", size, *f);
        history[k][1] = userTarget(c, k ? "user_history1_b" : "user_history0_b", size, *f);
      }
  }
};

UserResolvePass::UserResolvePass(vk::Context& ctx, const spec::CaseSpec& spec, UserShader shader)
    : impl_(std::make_unique<Impl>(ctx, spec, std::move(shader))) {}

UserResolvePass::~UserResolvePass() = default;

vk::Image& UserResolvePass::output() {
  return impl_->output[impl_->current];
}

glm::ivec2 UserResolvePass::outputSize() const {
  return userOutputSize(impl_->spec);
}

GBufferNeeds UserResolvePass::needs() const {
  return userNeeds(impl_->shader.interface);
}

std::vector<std::string> UserResolvePass::describe() const {
  const auto& s = *impl_;
  const glm::ivec2 size = userOutputSize(s.spec);
  const std::string dims = std::to_string(size.x) + "x" + std::to_string(size.y);
  std::vector<std::string> out;
  const auto& ui = s.shader.interface;
  out.push_back("pass user_resolve " + s.shader.file.string() + " (" +
                user::languageName(s.shader.language) + describeUserDefines(s.spec.taa) +
                ", SPIR-V " + s.shader.provenance + ") workgroup " +
                std::to_string(ui.workgroup[0]) + "x" + std::to_string(ui.workgroup[1]) +
                " params: " + describeAllParams(s.spec.taa, ui));
  for (const auto& note : userParamNotes(userParamValues(s.spec.taa, ui)))
    out.push_back("user shader note: " + note);
  out.push_back("buffer user output 2x " + dims + " rgba16f");
  for (int k = 0; k < 2; ++k)
    if (const auto f = s.shader.interface.history[k])
      out.push_back("buffer user history" + std::to_string(k) + " 2x " + dims + " " +
                    userFormatName(*f));
  return out;
}

void UserResolvePass::record(VkCommandBuffer cmd, vk::GpuTimer& timer,
                             const script::FrameState& state, int, const ResolveInputs& in) {
  auto& s = *impl_;
  const glm::ivec2 out = userOutputSize(s.spec);
  UserFrameUniforms u{};
  u.viewProj = state.camera.viewProjection;
  u.invViewProj = glm::inverse(state.camera.viewProjection);
  u.prevViewProj = state.prevCamera.viewProjection;
  u.renderSize = glm::vec4(glm::vec2(state.renderSize), 1.0f / glm::vec2(state.renderSize));
  u.outputSize = glm::vec4(glm::vec2(out), 1.0f / glm::vec2(out));
  const glm::vec2 prevJitter = state.resetHistory ? state.jitter : s.prevJitter;
  u.jitter = glm::vec4(state.jitter, prevJitter);
  u.camera = glm::vec4(state.camera.nearPlane, state.camera.farPlane, 0.0f, 0.0f);
  u.info = glm::uvec4(uint32_t(state.frame), state.resetHistory ? 0u : 1u, 0u, 0u);
  const double prevTime = script::frameTime(s.spec.script, std::max(0, state.frame - 1));
  u.time = glm::vec4(float(1.0 / double(s.spec.script.fps)), float(state.time), float(prevTime), 0.0f);
  const glm::ivec2 prevSize = state.frame == 0 || state.resetHistory ? state.renderSize : s.prevRenderSize;
  u.prevRenderSize = glm::vec4(glm::vec2(prevSize), 1.0f / glm::vec2(prevSize));
  // Every render-size input is allocated at the colour's size (the largest render size).
  const vk::Image* color = in[ResolveInput::Color];
  if (!color) throw std::logic_error("user resolve: no input colour");
  const glm::vec2 inputSize(float(color->desc().width), float(color->desc().height));
  u.inputSize = glm::vec4(inputSize, 1.0f / inputSize);
  std::memcpy(s.uniforms.mapped(), &u, sizeof(u));
  s.prevJitter = state.jitter;
  s.prevRenderSize = state.renderSize;

  const int previous = s.current;
  s.current ^= 1;
  const auto& ui = s.shader.interface;
  const vk::ShaderInterface& si = s.pipeline.interface();
  vk::Dispatch d(s.pipeline);
  // A GLSL shader samples through the sampler bound with each image (its row's filter); an
  // HLSL one declares textures and names taa_point_clamp or taa_linear_clamp itself.
  auto bindImage = [&](uint32_t binding, vk::Image& image, VkFilter filter) {
    const vk::ReflectedBinding* b = si.find(0, binding);
    if (b && b->type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE)
      d.texture(binding, image);
    else
      d.sample(binding, image, filter == VK_FILTER_LINEAR ? s.linear.handle() : s.point.handle());
  };
  d.uniform(user::kUserFrame, s.uniforms.handle(), 0, sizeof(UserFrameUniforms));
  if (s.params) d.uniform(user::kUserParams, s.params.handle(), 0, ui.uniformBytes);
  for (const ResolveInputInfo& i : kResolveInputs) {
    if (!ui.reads.has(i.input)) continue;
    vk::Image* image = i.source == InputSource::Own ? &s.output[previous] : in[i.input];
    if (!image)
      throw std::logic_error(std::string("user resolve: the plan did not allocate ") + i.name);
    bindImage(uint32_t(i.userBinding), *image, i.filter);
  }
  if (si.find(0, user::kUserPointSampler)) d.sampler(user::kUserPointSampler, s.point.handle());
  if (si.find(0, user::kUserLinearSampler)) d.sampler(user::kUserLinearSampler, s.linear.handle());
  d.store(user::kUserOutput, s.output[s.current]);
  for (int k = 0; k < 2; ++k)
    if (ui.history[k]) {
      bindImage(k ? user::kUserHistory1 : user::kUserHistory0, s.history[k][previous],
                VK_FILTER_LINEAR);
      d.store(k ? user::kUserHistory1Out : user::kUserHistory0Out, s.history[k][s.current]);
    }
  timer.begin(cmd, "user_resolve");
  d.record(s.ctx, cmd, uint32_t(out.x), uint32_t(out.y));
  timer.end(cmd);
}

}  // namespace taa

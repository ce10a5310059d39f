#include "user/user_resolve.h"

#include <cmath>
#include <cstring>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <stdexcept>

#include "passes/storage_image.h"
#include "user/glsl_compiler.h"
#include "vk/context.h"
#include "vk/dispatch.h"

namespace taa {

namespace {

// taa_user.h's TaaUserFrame, std140: matrices and vectors only, so no padding to mirror.
struct UserFrameUniforms {
  glm::mat4 viewProj;
  glm::mat4 invViewProj;
  glm::mat4 prevViewProj;
  glm::vec4 renderSize;
  glm::vec4 outputSize;
  glm::vec4 jitter;
  glm::vec4 camera;
  glm::uvec4 info;
};
static_assert(sizeof(UserFrameUniforms) == 3 * 64 + 5 * 16, "TaaUserFrame layout (taa_user.h)");

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
std::string userParamBits(user::ParamType t, double v, uint32_t& bits) {
  using user::ParamType;
  const bool whole = std::floor(v) == v;
  switch (t) {
    case ParamType::Bool:
      if (v != 0.0 && v != 1.0) return "a bool takes 0 (false) or 1 (true)";
      bits = v != 0.0;
      return {};
    case ParamType::Int:
      if (!whole || v < -2147483648.0 || v > 2147483647.0)
        return "an int takes a whole number from -2147483648 to 2147483647";
      bits = uint32_t(int32_t(int64_t(v)));
      return {};
    case ParamType::Uint:
      if (!whole || v < 0.0 || v > 4294967295.0)
        return "a uint takes a whole number from 0 to 4294967295";
      bits = uint32_t(int64_t(v));
      return {};
    case ParamType::Float: {
      if (std::fabs(v) > 3.4028234663852886e38) return "a float takes a number within float range";
      const float f = float(v);
      std::memcpy(&bits, &f, 4);
      return {};
    }
  }
  return "unknown type";
}

glm::ivec2 userOutputSize(const spec::CaseSpec& s) {
  return {s.render.width, s.render.height};
}

}  // namespace

UserShader loadUserShader(const spec::CaseSpec& spec) {
  const auto root =
      spec.file.parent_path().empty() ? std::filesystem::path(".") : spec.file.parent_path();
  // An absolute taa.shader only comes from `taa-harness score`, which names the shader on its
  // command line; its folder is then the include root. Case files are refused one (validation).
  const std::filesystem::path file = std::filesystem::path(spec.taa.shader).is_absolute()
                                         ? std::filesystem::path(spec.taa.shader)
                                         : root / spec.taa.shader;
  user::CompileOptions o;
  o.root = std::filesystem::path(spec.taa.shader).is_absolute() ? file.parent_path() : root;
  user::CompiledShader c = user::compileComputeShader(file, o);
  UserShader out;
  out.file = file;
  out.fromCache = c.fromCache;
  try {
    out.interface = user::reflectUserInterface(c.spirv, file.string());
  } catch (const std::runtime_error& e) {
    throw user::ShaderCompileError(std::string(e.what()) + " (see docs/user-taa.md)");
  }
  out.spirv = std::move(c.spirv);
  return out;
}

std::vector<std::string> userParamProblems(const spec::TaaSpec& taa, const user::UserInterface& u) {
  std::vector<std::string> out;
  std::string declared;
  for (const auto& p : u.params)
    declared += (declared.empty() ? "" : ", ") + p.name + " (" + user::paramTypeName(p.type) + ")";
  if (declared.empty()) declared = "none";
  for (size_t i = 0; i < taa.shader_params.size(); ++i) {
    const auto& sp = taa.shader_params[i];
    const std::string key = "taa.shader_params[" + std::to_string(i) + "]";
    const user::UserParam* p = u.param(sp.name);
    if (!p) {
      out.push_back(key + ".name: '" + sp.name + "' is not a specialization constant of " +
                    taa.shader + "; it declares: " + declared);
      continue;
    }
    for (size_t j = 0; j < i; ++j)
      if (taa.shader_params[j].name == sp.name)
        out.push_back(key + ".name: '" + sp.name + "' is set twice; remove one");
    uint32_t bits = 0;
    if (const std::string why = userParamBits(p->type, sp.value, bits); !why.empty())
      out.push_back(key + ".value: " + sp.name + " is declared " + user::paramTypeName(p->type) +
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

GBufferNeeds userNeeds(const user::UserInterface& u) {
  GBufferNeeds n;
  n.depth = u.depth;
  n.velocity = u.velocity;
  // Last frame's ids and normals are copies of this frame's targets.
  n.ids = u.ids || u.prevIds;
  n.normal = u.normal || u.prevNormal;
  n.prevDepth = u.prevDepth;
  n.prevIds = u.prevIds;
  n.prevNormal = u.prevNormal;
  return n;
}

struct UserResolvePass::Impl {
  vk::Context& ctx;
  const spec::CaseSpec& spec;
  UserShader shader;
  vk::Pipeline pipeline;
  vk::Image output[2];
  vk::Image history[2][2];  // [target][ping-pong]
  vk::Buffer uniforms;
  vk::Sampler linear, point;
  int current = 0;
  glm::vec2 prevJitter{0.0f};

  Impl(vk::Context& c, const spec::CaseSpec& s, UserShader sh)
      : ctx(c),
        spec(s),
        shader(std::move(sh)),
        uniforms(c, sizeof(UserFrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true),
        linear(c, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE),
        point(c, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE) {
    pipeline = vk::createComputePipelineFromSpirv(c, shader.file.filename().string(), shader.spirv,
                                                  userSpecConstants(s.taa, shader.interface));
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
  out.push_back("pass user_resolve " + s.shader.file.string() +
                (s.shader.fromCache ? " (SPIR-V from cache)" : "") +
                " spec constants: " + userSpecConstants(s.spec.taa, s.shader.interface).describe());
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
  std::memcpy(s.uniforms.mapped(), &u, sizeof(u));
  s.prevJitter = state.jitter;

  const int previous = s.current;
  s.current ^= 1;
  const auto& ui = s.shader.interface;
  vk::Dispatch d(s.pipeline);
  d.uniform(user::kUserFrame, s.uniforms.handle(), 0, sizeof(UserFrameUniforms));
  auto bind = [&](bool declared, uint32_t binding, vk::Image* image, const char* what) {
    if (!declared) return;
    if (!image)
      throw std::logic_error(std::string("user resolve: the plan did not allocate ") + what);
    d.sample(binding, *image, s.point.handle());
  };
  bind(true, user::kUserColor, in.color, "colour");
  bind(ui.depth, user::kUserDepth, in.depth, "depth");
  bind(ui.velocity, user::kUserVelocity, in.velocity, "velocity");
  bind(ui.ids, user::kUserIds, in.ids, "ids");
  bind(ui.normal, user::kUserNormal, in.normal, "normals");
  bind(ui.prevDepth, user::kUserPrevDepth, in.prevDepth, "previous depth");
  bind(ui.prevIds, user::kUserPrevIds, in.prevIds, "previous ids");
  bind(ui.prevNormal, user::kUserPrevNormal, in.prevNormal, "previous normals");
  d.sample(user::kUserPrevOutput, s.output[previous], s.linear.handle());
  d.store(user::kUserOutput, s.output[s.current]);
  for (int k = 0; k < 2; ++k)
    if (ui.history[k]) {
      d.sample(k ? user::kUserHistory1 : user::kUserHistory0, s.history[k][previous],
               s.linear.handle());
      d.store(k ? user::kUserHistory1Out : user::kUserHistory0Out, s.history[k][s.current]);
    }
  timer.begin(cmd, "user_resolve");
  d.record(s.ctx, cmd, uint32_t(out.x), uint32_t(out.y));
  timer.end(cmd);
}

}  // namespace taa

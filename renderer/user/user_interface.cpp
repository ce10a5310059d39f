#include "user/user_interface.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <optional>
#include <string_view>

#include "user/glsl_compiler.h"
#include "user/shader_bounds.h"
#include "vk/spirv_reflect.h"

namespace taa::user {

namespace {

static_assert(resolveInputBindingsValid({}, {kUserFrame, kUserOutput, kUserHistory0,
                                             kUserHistory0Out, kUserHistory1, kUserHistory1Out,
                                             kUserPointSampler, kUserLinearSampler}),
              "two inputs of a user's resolve share a binding in common/resolve_inputs.h, or one "
              "takes a binding of its own targets");

// The SPIR-V opcodes and decorations read here (SPIR-V specification, section 3).
constexpr uint32_t kUserOpName = 5, kUserOpMemberName = 6, kUserOpTypeBool = 20,
                   kUserOpTypeInt = 21, kUserOpTypeFloat = 22, kUserOpTypeVector = 23,
                   kUserOpTypeMatrix = 24, kUserOpTypeImage = 25, kUserOpTypeSampledImage = 27,
                   kUserOpTypeStruct = 30, kUserOpTypePointer = 32, kUserOpSpecTrue = 48,
                   kUserOpSpecFalse = 49, kUserOpSpec = 50, kUserOpVariable = 59,
                   kUserOpDecorate = 71, kUserOpMemberDecorate = 72;
constexpr uint32_t kUserDecoSpecId = 1, kUserDecoRowMajor = 4, kUserDecoMatrixStride = 7,
                   kUserDecoBinding = 33, kUserDecoOffset = 35;
constexpr uint32_t kUserDim2D = 1, kUserFormatRgba16f = 2;

// What taa_user.h declares at a binding of set 0, and so what the harness binds there: the
// inputs' rows of resolve_inputs.h, then its own frame constants, output, histories and the
// two samplers an HLSL resolve names.
struct UserSlot {
  const char* name;
  bool sampled;           // an image it samples: a sampler2D (GLSL) or a Texture2D (HLSL)
  VkDescriptorType type;  // otherwise the one descriptor type it declares
  bool uintSamples;       // usampler2D (the ids); every other image holds floats
};

std::optional<UserSlot> userSlot(uint32_t binding) {
  for (const ResolveInputInfo& i : kResolveInputs)
    if (i.userBinding >= 0 && uint32_t(i.userBinding) == binding)
      return UserSlot{i.userName, true, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, i.uintTexels};
  constexpr VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                             sampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                             sampler = VK_DESCRIPTOR_TYPE_SAMPLER;
  switch (binding) {
    case kUserFrame:
      return UserSlot{"taa_frame", false, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, false};
    case kUserOutput:
      return UserSlot{"taa_output", false, storage, false};
    case kUserHistory0:
      return UserSlot{"taa_history0", true, sampled, false};
    case kUserHistory0Out:
      return UserSlot{"taa_history0_out", false, storage, false};
    case kUserHistory1:
      return UserSlot{"taa_history1", true, sampled, false};
    case kUserHistory1Out:
      return UserSlot{"taa_history1_out", false, storage, false};
    case kUserPointSampler:
      return UserSlot{"taa_point_clamp", false, sampler, false};
    case kUserLinearSampler:
      return UserSlot{"taa_linear_clamp", false, sampler, false};
    case kUserParams:
      return UserSlot{"the loose uniforms ($Global)", false, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                      false};
    default:
      return std::nullopt;
  }
}

// sizeof(TaaUserFrame): its members are mat4s and 16-byte vectors (common/user_frame.h).
#define TAA_USER_FRAME_MEMBER_BYTES(type, name, doc) +(std::string_view(#type) == "mat4" ? 64u : 16u)
constexpr uint32_t kUserFrameBytes = 0 TAA_USER_FRAME(TAA_USER_FRAME_MEMBER_BYTES);
#undef TAA_USER_FRAME_MEMBER_BYTES

// SPIR-V image formats (section 3.11) a history target may declare.
VkFormat userHistoryFormat(uint32_t spirvFormat) {
  switch (spirvFormat) {
    case 1:
      return VK_FORMAT_R32G32B32A32_SFLOAT;  // rgba32f
    case 2:
      return VK_FORMAT_R16G16B16A16_SFLOAT;  // rgba16f
    case 3:
      return VK_FORMAT_R32_SFLOAT;  // r32f
    case 6:
      return VK_FORMAT_R32G32_SFLOAT;  // rg32f
    case 7:
      return VK_FORMAT_R16G16_SFLOAT;  // rg16f
    case 9:
      return VK_FORMAT_R16_SFLOAT;  // r16f
    default:
      return VK_FORMAT_UNDEFINED;
  }
}

std::string userOperandString(const std::vector<uint32_t>& w, size_t at, size_t end) {
  std::string s;
  for (size_t i = at; i < end; ++i)
    for (int b = 0; b < 4; ++b) {
      const char c = char((w[i] >> (8 * b)) & 0xffu);
      if (c == 0) return s;
      s += c;
    }
  return s;
}

}  // namespace

const char* paramTypeName(ParamType t) {
  switch (t) {
    case ParamType::Bool:
      return "bool";
    case ParamType::Int:
      return "int";
    case ParamType::Uint:
      return "uint";
    case ParamType::Float:
      return "float";
  }
  return "?";
}

std::optional<ParamType> paramTypeNamed(const std::string& name) {
  for (const ParamType t : {ParamType::Bool, ParamType::Int, ParamType::Uint, ParamType::Float})
    if (name == paramTypeName(t)) return t;
  return std::nullopt;
}

const UserParam* UserInterface::param(const std::string& name) const {
  for (const auto& p : params)
    if (p.name == name) return &p;
  return nullptr;
}

const DeclaredConstant* UserInterface::unreadParam(const std::string& name) const {
  for (const auto& c : unread)
    if (c.name == name) return &c;
  return nullptr;
}

const UserUniform* UserInterface::uniform(const std::string& name) const {
  for (const auto& m : uniforms)
    if (m.name == name) return &m;
  return nullptr;
}

std::string UserUniform::typeName() const {
  if (!supported) return "array or struct";
  std::string t = paramTypeName(type);
  if (columns > 1) return t + std::to_string(columns) + "x" + std::to_string(rows);
  return rows > 1 ? t + std::to_string(rows) : t;
}

void noteUnreadConstants(UserInterface& u, const std::vector<DeclaredConstant>& declared) {
  u.unread.clear();
  for (const auto& c : declared)
    if (!u.param(c.name) && !u.unreadParam(c.name)) u.unread.push_back(c);
}

namespace {

// The bindings and push constants against taa_user.h: whatever else a shader
// declares, the harness would not bind, and Vulkan leaves the result undefined.
void checkUserBindings(const vk::ShaderInterface& si, const std::string& name) {
  auto refuse = [&](const std::string& why) {
    throw ShaderCompileError(name + " " + why +
                             "; a resolve may declare only what taa_user.h declares (include it "
                             "and use its names)");
  };
  if (si.pushConstantBytes > 0)
    refuse("declares a push-constant block (" + std::to_string(si.pushConstantBytes) +
           " bytes), which taa_user.h does not have; use a specialization constant and "
           "taa.shader_params");
  for (const auto& b : si.bindings) {
    const std::string at = "set " + std::to_string(b.set) + " binding " + std::to_string(b.binding);
    const std::string what = std::string(vk::descriptorTypeName(b.type)) + " at " + at;
    if (b.set != 0) refuse("declares a " + what + "; taa_user.h uses set 0 only");
    const std::optional<UserSlot> slot = userSlot(b.binding);
    if (!slot) refuse("declares a " + what + ", a binding taa_user.h does not declare");
    const bool fits = slot->sampled ? b.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER ||
                                          b.type == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE
                                    : b.type == slot->type;
    if (!fits)
      refuse("declares a " + what + ", where taa_user.h declares " + slot->name + ", " +
             (slot->sampled ? std::string("an image it samples (sampler2D or Texture2D)")
                            : std::string("a ") + vk::descriptorTypeName(slot->type)));
    if (b.count != 1)
      refuse("declares an array of " + std::to_string(b.count) + " at " + at + ", where taa_user.h declares one " +
             slot->name);
    if (b.binding == kUserParams && b.bytes > kMaxUserUniformBytes)
      refuse("declares " + std::to_string(b.bytes) + " bytes of loose uniforms ($Global) at " + at +
             ", over the bound of " + std::to_string(kMaxUserUniformBytes) +
             " bytes; move tables into a texture or make them static");
    if (b.binding == kUserFrame && b.bytes > kUserFrameBytes)
      refuse("declares a " + std::to_string(b.bytes) + "-byte uniform block at " + at +
             ", larger than taa_user.h's TaaUserFrame (" + std::to_string(kUserFrameBytes) +
             " bytes): it would read past the harness's buffer");
  }
}

// The image types behind the bindings: 2D, single-sampled, not arrayed, float samples but for
// the ids' uint, and taa_output's rgba16f. `defs` maps type ids to their operands.
void checkUserImages(const std::map<uint32_t, std::vector<uint32_t>>& defs,
                     const std::map<uint32_t, uint32_t>& types,
                     const std::vector<std::pair<uint32_t, uint32_t>>& variables,
                     const std::map<uint32_t, uint32_t>& bindings, const std::string& name) {
  auto def = [&](uint32_t id) -> const std::vector<uint32_t>& {
    static const std::vector<uint32_t> none;
    const auto it = defs.find(id);
    return it == defs.end() ? none : it->second;
  };
  auto typeOf = [&](uint32_t id) {
    const auto it = types.find(id);
    return it == types.end() ? 0u : it->second;
  };
  for (const auto& [pointer, id] : variables) {
    const auto b = bindings.find(id);
    if (b == bindings.end()) continue;
    const std::optional<UserSlot> slot = userSlot(b->second);
    const auto& ptr = def(pointer);
    if (!slot || ptr.size() < 3) continue;
    uint32_t imageId = ptr[2];
    if (typeOf(imageId) == kUserOpTypeSampledImage && def(imageId).size() >= 2)
      imageId = def(imageId)[1];
    if (typeOf(imageId) != kUserOpTypeImage) continue;
    const auto& image = def(imageId);
    if (image.size() < 8) continue;
    const std::string at = std::string(slot->name) + " (binding " + std::to_string(b->second) + ")";
    auto refuse = [&](const std::string& why) {
      throw ShaderCompileError(name + " declares " + at + " " + why +
                               "; declare it as taa_user.h does (include the header)");
    };
    if (image[2] != kUserDim2D || image[4] != 0 || image[5] != 0)
      refuse("as another image than a single-sampled, non-arrayed 2D one");
    const auto& sampled = def(image[1]);
    const bool isUint = typeOf(image[1]) == kUserOpTypeInt && sampled.size() >= 3 && sampled[2] == 0;
    const bool isFloat = typeOf(image[1]) == kUserOpTypeFloat;
    if (slot->uintSamples ? !isUint : !isFloat)
      refuse(std::string("with ") + (isUint ? "uint" : isFloat ? "float" : "int") +
             " samples, where the harness binds " + (slot->uintSamples ? "uint" : "float") +
             " data (" + (slot->uintSamples ? "usampler2D" : "sampler2D or image2D") + ")");
    if (b->second == kUserOutput && image[7] != kUserFormatRgba16f)
      refuse("with another format than rgba16f, the format of the harness's output image");
  }
}

}  // namespace

UserInterface reflectUserInterface(const std::vector<uint32_t>& w, const std::string& name) {
  // Descriptor types and presence come from the layer every pipeline uses.
  const vk::ShaderInterface si = vk::reflectSpirv(w, name);
  checkUserBindings(si, name);
  if (const std::string why = spirvMemoryProblem(w); !why.empty())
    throw ShaderCompileError(name + ": " + why);
  auto has = [&](uint32_t b) { return si.find(0, b) != nullptr; };
  UserInterface u;
  if (!has(kUserOutput))
    throw ShaderCompileError(
        name + " never writes taa_output (binding 10); a resolve must imageStore its result there");
  for (const ResolveInputInfo& i : kResolveInputs)
    if (i.userBinding >= 0 && has(uint32_t(i.userBinding))) u.reads |= {i.input};
  // One invocation per output pixel: a deeper group would write each pixel more than once,
  // and a size the case's shader_params could change would not be the one dispatched.
  const auto& ls = si.localSize;
  const std::string size =
      std::to_string(ls[0]) + "x" + std::to_string(ls[1]) + "x" + std::to_string(ls[2]);
  if (si.localSizeSpecId[0] >= 0 || si.localSizeSpecId[1] >= 0 || si.localSizeSpecId[2] >= 0)
    throw ShaderCompileError(name + ": its workgroup size is set by specialization constants; "
                                    "declare it with numbers (local_size_x = 16, or HLSL's "
                                    "[numthreads(16, 16, 1)])");
  if (ls[2] != 1 || uint64_t(ls[0]) * ls[1] > kMaxUserWorkgroupInvocations)
    throw ShaderCompileError(name + ": declares a workgroup of " + size +
                             "; a resolve's workgroup is X x Y x 1 with at most " +
                             std::to_string(kMaxUserWorkgroupInvocations) + " invocations");
  u.workgroup[0] = ls[0];
  u.workgroup[1] = ls[1];

  std::map<uint32_t, std::string> names;
  std::map<uint32_t, uint32_t> specIds, bindings, types;  // types: id -> opcode
  std::map<uint32_t, std::vector<uint32_t>> defs;         // type / constant id -> operands
  std::vector<std::pair<uint32_t, uint32_t>> variables;   // pointer type, id
  std::vector<uint32_t> specConstants;
  std::map<std::pair<uint32_t, uint32_t>, std::string> memberNames;  // (struct, member)
  std::map<std::pair<uint32_t, uint32_t>, std::map<uint32_t, uint32_t>> memberDecorations;
  for (size_t i = 5; i < w.size();) {
    const uint32_t count = w[i] >> 16, opcode = w[i] & 0xffffu;
    if (count == 0 || i + count > w.size())
      throw ShaderCompileError("SPIR-V of " + name + " is truncated");
    const std::vector<uint32_t> ops(w.begin() + long(i) + 1, w.begin() + long(i + count));
    if (opcode == kUserOpName && ops.size() >= 2)
      names[ops[0]] = userOperandString(w, i + 2, i + count);
    if (opcode == kUserOpDecorate && ops.size() >= 3 && ops[1] == kUserDecoSpecId)
      specIds[ops[0]] = ops[2];
    if (opcode == kUserOpDecorate && ops.size() >= 3 && ops[1] == kUserDecoBinding)
      bindings[ops[0]] = ops[2];
    if (opcode == kUserOpMemberName && ops.size() >= 3)
      memberNames[{ops[0], ops[1]}] = userOperandString(w, i + 3, i + count);
    if (opcode == kUserOpMemberDecorate && ops.size() >= 3)
      memberDecorations[{ops[0], ops[1]}][ops[2]] = ops.size() >= 4 ? ops[3] : 1u;
    if (opcode == kUserOpTypeBool || opcode == kUserOpTypeInt || opcode == kUserOpTypeFloat ||
        opcode == kUserOpTypeImage || opcode == kUserOpTypeSampledImage ||
        opcode == kUserOpTypePointer || opcode == kUserOpTypeVector ||
        opcode == kUserOpTypeMatrix || opcode == kUserOpTypeStruct) {
      types[ops[0]] = opcode;
      defs[ops[0]] = ops;
    }
    if (opcode == kUserOpSpecTrue || opcode == kUserOpSpecFalse || opcode == kUserOpSpec) {
      defs[ops[1]] = ops;
      types[ops[1]] = opcode;
      specConstants.push_back(ops[1]);
    }
    if (opcode == kUserOpVariable && ops.size() >= 3) variables.emplace_back(ops[0], ops[1]);
    i += count;
  }

  checkUserImages(defs, types, variables, bindings, name);
  if (const vk::ReflectedBinding* b = si.find(0, kUserParams)) {
    u.uniformBytes = b->bytes;
    for (const auto& [pointer, id] : variables) {
      const auto bound = bindings.find(id);
      if (bound == bindings.end() || bound->second != kUserParams) continue;
      const auto& ptr = defs[pointer];
      if (ptr.size() < 3 || types[ptr[2]] != kUserOpTypeStruct) continue;
      const uint32_t block = ptr[2];
      u.uniformBlock = names.count(block) ? names[block] : "";
      const auto& members = defs[block];
      for (uint32_t m = 0; m + 1 < members.size(); ++m) {
        UserUniform uu;
        const auto key = std::make_pair(block, m);
        uu.name = memberNames.count(key) ? memberNames[key] : "";
        auto& deco = memberDecorations[key];
        uu.offset = deco.count(kUserDecoOffset) ? deco[kUserDecoOffset] : 0u;
        uu.matrixStride = deco.count(kUserDecoMatrixStride) ? deco[kUserDecoMatrixStride] : 0u;
        uu.rowMajor = deco.count(kUserDecoRowMajor) > 0;
        uint32_t t = members[m + 1];
        if (types[t] == kUserOpTypeMatrix && defs[t].size() >= 3) {
          uu.columns = defs[t][2];
          t = defs[t][1];
        }
        if (types[t] == kUserOpTypeVector && defs[t].size() >= 3) {
          uu.rows = defs[t][2];
          t = defs[t][1];
        }
        const uint32_t scalar = types[t];
        uu.supported = scalar == kUserOpTypeFloat || scalar == kUserOpTypeInt;
        uu.type = scalar == kUserOpTypeFloat                ? ParamType::Float
                  : defs[t].size() >= 3 && defs[t][2] != 0u ? ParamType::Int
                                                            : ParamType::Uint;
        // Only 32-bit components: the values are written as 4-byte words.
        if (uu.supported && (defs[t].size() < 2 || defs[t][1] != 32u)) uu.supported = false;
        if (uu.columns > 1 && uu.matrixStride == 0) uu.supported = false;
        // Its last byte: a matrix's last column (or row, if row-major) starts a stride before.
        const uint64_t lines = uu.rowMajor ? uu.rows : uu.columns,
                       width = uu.columns > 1 ? (uu.rowMajor ? uu.columns : uu.rows) : uu.rows;
        const uint64_t end =
            uint64_t(uu.offset) + uint64_t(uu.matrixStride) * (lines - 1) + width * 4u;
        if (end > u.uniformBytes) uu.supported = false;
        if (!uu.name.empty()) u.uniforms.push_back(uu);
      }
    }
  }

  for (const uint32_t id : specConstants) {
    const auto sid = specIds.find(id);
    if (sid == specIds.end()) continue;  // a constant derived from others, not settable
    const auto n = names.find(id);
    if (n == names.end() || n->second.empty())
      throw ShaderCompileError(
          name + ": specialization constant " + std::to_string(sid->second) +
          " has no name; declare it as `layout(constant_id = N) const T name = ...;`");
    if (sid->second > kMaxUserConstantId)
      throw ShaderCompileError(name + ": specialization constant " + n->second +
                               " has constant_id " + std::to_string(sid->second) +
                               "; taa_user.h allows 0 to " + std::to_string(kMaxUserConstantId));
    const auto& ops = defs[id];
    UserParam p;
    p.name = n->second;
    p.specId = sid->second;
    const uint32_t typeOp = types[ops[0]];
    if (typeOp == kUserOpTypeBool) {
      p.type = ParamType::Bool;
      p.defaultBits = types[id] == kUserOpSpecTrue ? 1u : 0u;
    } else {
      p.type = typeOp == kUserOpTypeFloat                    ? ParamType::Float
               : defs[ops[0]].size() >= 3 && defs[ops[0]][2] ? ParamType::Int
                                                             : ParamType::Uint;
      p.defaultBits = ops.size() >= 3 ? ops[2] : 0u;
    }
    // Constants the header itself declares (the workgroup size) are not the user's to set.
    if (p.name.rfind("taa_", 0) == 0) continue;
    u.params.push_back(p);
  }

  // SPIR-V orders constants by type, not by declaration: list them by constant_id.
  std::sort(u.params.begin(), u.params.end(),
            [](const UserParam& a, const UserParam& b) { return a.specId < b.specId; });

  // History k: its write image's declared format.
  for (int k = 0; k < 2; ++k) {
    const uint32_t in = k ? kUserHistory1 : kUserHistory0,
                   out = k ? kUserHistory1Out : kUserHistory0Out;
    if (!has(out)) {
      if (has(in))
        throw ShaderCompileError(name + " reads history " + std::to_string(k) +
                                 " but never writes it; define TAA_HISTORY" + std::to_string(k) +
                                 "_FORMAT and imageStore taa_history" + std::to_string(k) + "_out");
      continue;
    }
    for (const auto& [pointer, id] : variables) {
      const auto b = bindings.find(id);
      if (b == bindings.end() || b->second != out) continue;
      const auto& ptr = defs[pointer];
      const auto& image = ptr.size() >= 3 ? defs[ptr[2]] : std::vector<uint32_t>{};
      const VkFormat f = image.size() >= 8 ? userHistoryFormat(image[7]) : VK_FORMAT_UNDEFINED;
      if (f == VK_FORMAT_UNDEFINED)
        throw ShaderCompileError(
            name + ": history " + std::to_string(k) +
            " has an unsupported format; use rgba16f, rgba32f, rg16f, rg32f, r16f or r32f");
      u.history[k] = f;
    }
  }
  return u;
}

}  // namespace taa::user

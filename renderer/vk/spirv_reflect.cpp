#include "vk/spirv_reflect.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace taa::vk {

namespace {

// The few SPIR-V enumerants reflection reads (SPIR-V 1.x specification, section 3).
namespace op {
constexpr uint32_t Name = 5, EntryPoint = 15, ExecutionMode = 16, TypeBool = 20, TypeInt = 21, TypeFloat = 22,
                   TypeVector = 23, TypeMatrix = 24, TypeImage = 25, TypeSampler = 26,
                   TypeSampledImage = 27, TypeArray = 28, TypeRuntimeArray = 29, TypeStruct = 30,
                   TypePointer = 32, Constant = 43, ConstantComposite = 44, SpecConstant = 50,
                   SpecConstantComposite = 51, Variable = 59, Decorate = 71, MemberDecorate = 72,
                   TypeAccelerationStructure = 5341;
}  // namespace op
namespace deco {
constexpr uint32_t SpecId = 1, Block = 2, BufferBlock = 3, ArrayStride = 6, MatrixStride = 7,
                   BuiltIn = 11, Binding = 33, DescriptorSet = 34, Offset = 35;
}  // namespace deco
constexpr uint32_t kSpirvMagic = 0x07230203u;
constexpr uint32_t kModeLocalSize = 17;
constexpr uint32_t kBuiltInWorkgroupSize = 25;
constexpr uint32_t kStorageUniformConstant = 0, kStorageUniform = 2, kStoragePushConstant = 9,
                   kStorageBuffer = 12;
constexpr uint32_t kDimBuffer = 5, kDimSubpassData = 6;

struct Decorations {
  int64_t set = -1, binding = -1, specId = -1, builtIn = -1;
  bool block = false, bufferBlock = false;
  uint32_t arrayStride = 0;
};

struct Instruction {
  uint32_t opcode;
  std::vector<uint32_t> operands;
};

struct Module {
  std::string name;
  std::unordered_map<uint32_t, Instruction> defs;  // types and constants by result id
  std::unordered_map<uint32_t, Decorations> decorations;
  std::unordered_map<uint32_t, std::vector<uint32_t>> memberOffsets;  // struct -> per member
  std::unordered_map<uint32_t, std::vector<uint32_t>> memberMatrixStrides;
  std::vector<std::array<uint32_t, 3>> variables;  // pointer type, id, storage class
  std::unordered_map<uint32_t, std::string> names;   // OpName, where the compiler kept them

  [[noreturn]] void fail(const std::string& what) const {
    throw ShaderInterfaceError("SPIR-V of " + name + ": " + what);
  }
  const Instruction& def(uint32_t id) const {
    const auto it = defs.find(id);
    if (it == defs.end()) fail("id " + std::to_string(id) + " is used but never defined");
    return it->second;
  }
  uint32_t operand(const Instruction& i, size_t k) const {
    if (k >= i.operands.size()) fail("opcode " + std::to_string(i.opcode) + " is too short");
    return i.operands[k];
  }
  uint32_t constantValue(uint32_t id) const {
    const Instruction& c = def(id);
    if (c.opcode != op::Constant && c.opcode != op::SpecConstant)
      fail("id " + std::to_string(id) + " is not a scalar constant");
    return operand(c, 2);
  }
};

uint32_t saturated(uint64_t v) {
  return v > UINT32_MAX ? UINT32_MAX : uint32_t(v);
}

// Byte size of a type inside a push-constant or buffer block (offsets come from the Offset
// decorations; sizes of members from their types and strides), saturating at 2^32 - 1.
uint32_t typeBytes(const Module& m, uint32_t typeId, uint32_t matrixStride = 0) {
  const Instruction& t = m.def(typeId);
  switch (t.opcode) {
    case op::TypeBool:
      return 4;
    case op::TypeInt:
    case op::TypeFloat:
      return m.operand(t, 1) / 8;
    case op::TypeVector:
      return saturated(uint64_t(m.operand(t, 2)) * typeBytes(m, m.operand(t, 1)));
    case op::TypeMatrix: {
      const uint32_t columns = m.operand(t, 2);
      return saturated(uint64_t(columns) *
                       (matrixStride ? matrixStride : typeBytes(m, m.operand(t, 1))));
    }
    case op::TypeArray: {
      const uint32_t length = m.constantValue(m.operand(t, 2));
      const auto d = m.decorations.find(typeId);
      const uint32_t stride = d != m.decorations.end() && d->second.arrayStride
                                  ? d->second.arrayStride
                                  : typeBytes(m, m.operand(t, 1));
      return saturated(uint64_t(length) * stride);
    }
    case op::TypeStruct: {
      const auto offsets = m.memberOffsets.find(typeId);
      const auto strides = m.memberMatrixStrides.find(typeId);
      uint32_t end = 0;
      for (size_t k = 1; k < t.operands.size(); ++k) {
        const size_t member = k - 1;
        const uint32_t offset = offsets != m.memberOffsets.end() && member < offsets->second.size()
                                    ? offsets->second[member]
                                    : end;
        const uint32_t stride =
            strides != m.memberMatrixStrides.end() && member < strides->second.size()
                ? strides->second[member]
                : 0;
        end = std::max(end, saturated(uint64_t(offset) + typeBytes(m, t.operands[k], stride)));
      }
      return end;
    }
    case op::TypeRuntimeArray:
      return 0;  // a buffer's unsized last member: its size is the buffer's
    default:
      m.fail("block member of unsupported type (opcode " + std::to_string(t.opcode) + ")");
  }
}

VkDescriptorType imageType(const Module& m, const Instruction& image) {
  const uint32_t dim = m.operand(image, 2), sampled = m.operand(image, 6);
  if (dim == kDimSubpassData) return VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
  if (dim == kDimBuffer)
    return sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                        : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
  return sampled == 2 ? VK_DESCRIPTOR_TYPE_STORAGE_IMAGE : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
}

// The descriptor a resource variable needs: its type (arrays unwrapped into `count`)
// and storage class decide it.
ReflectedBinding bindingOf(const Module& m, uint32_t pointee, uint32_t storage) {
  ReflectedBinding b;
  const Instruction* t = &m.def(pointee);
  uint32_t typeId = pointee;
  while (t->opcode == op::TypeArray || t->opcode == op::TypeRuntimeArray) {
    if (t->opcode == op::TypeRuntimeArray)
      m.fail("runtime-sized descriptor arrays are not supported (give the array a size)");
    b.count *= m.constantValue(m.operand(*t, 2));
    typeId = m.operand(*t, 1);
    t = &m.def(typeId);
  }
  const auto d = m.decorations.find(typeId);
  const bool block = d != m.decorations.end() && d->second.block;
  const bool bufferBlock = d != m.decorations.end() && d->second.bufferBlock;
  switch (t->opcode) {
    case op::TypeSampledImage:
      b.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
      break;
    case op::TypeImage:
      b.type = imageType(m, *t);
      break;
    case op::TypeSampler:
      b.type = VK_DESCRIPTOR_TYPE_SAMPLER;
      break;
    case op::TypeAccelerationStructure:
      b.type = VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR;
      break;
    case op::TypeStruct:
      if (storage == kStorageBuffer || (storage == kStorageUniform && bufferBlock))
        b.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      else if (storage == kStorageUniform && block)
        b.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
      if (b.type != VK_DESCRIPTOR_TYPE_MAX_ENUM) b.bytes = typeBytes(m, typeId);
      break;
    default:
      break;
  }
  if (b.type == VK_DESCRIPTOR_TYPE_MAX_ENUM)
    m.fail("a resource of opcode " + std::to_string(t->opcode) + " in storage class " +
           std::to_string(storage) + " maps to no descriptor type");
  return b;
}

VkShaderStageFlags stageOf(const Module& m, uint32_t executionModel) {
  switch (executionModel) {
    case 0:
      return VK_SHADER_STAGE_VERTEX_BIT;
    case 4:
      return VK_SHADER_STAGE_FRAGMENT_BIT;
    case 5:
      return VK_SHADER_STAGE_COMPUTE_BIT;
    default:
      m.fail("unsupported execution model " + std::to_string(executionModel));
  }
}

// The workgroup size of a WorkgroupSize built-in: its components may be specialization
// constants, whose ids override LocalSize.
void readWorkgroupBuiltIn(const Module& m, uint32_t compositeId, ShaderInterface& out) {
  const Instruction& c = m.def(compositeId);
  for (size_t k = 0; k < 3; ++k) {
    const uint32_t component = m.operand(c, 2 + k);
    out.localSize[k] = m.constantValue(component);
    const auto d = m.decorations.find(component);
    out.localSizeSpecId[k] = d != m.decorations.end() ? int32_t(d->second.specId) : -1;
  }
}

// A nul-terminated literal string from operand `from` on, four bytes a word.
std::string literalString(const std::vector<uint32_t>& ops, size_t from) {
  std::string out;
  for (size_t w = from; w < ops.size(); ++w)
    for (int b = 0; b < 4; ++b) {
      const char c = char((ops[w] >> (8 * b)) & 0xffu);
      if (c == 0) return out;
      out += c;
    }
  return out;
}

// A variable as a message names it: its source name where the module kept one.
std::string variableName(const Module& m, uint32_t id) {
  const auto it = m.names.find(id);
  return it != m.names.end() && !it->second.empty() ? it->second : "variable " + std::to_string(id);
}

}  // namespace

const ReflectedBinding* ShaderInterface::find(uint32_t set, uint32_t binding) const {
  for (const auto& b : bindings)
    if (b.set == set && b.binding == binding) return &b;
  return nullptr;
}

ShaderInterface reflectSpirv(const std::vector<uint32_t>& words, const std::string& name) {
  Module m;
  m.name = name;
  if (words.size() < 5 || words[0] != kSpirvMagic) m.fail("not a SPIR-V module (bad header)");
  ShaderInterface out;
  int entryPoints = 0;
  for (size_t at = 5; at < words.size();) {
    const uint32_t count = words[at] >> 16, opcode = words[at] & 0xffffu;
    if (count == 0 || at + count > words.size())
      m.fail("instruction at word " + std::to_string(at) + " runs past the end");
    Instruction in{opcode, std::vector<uint32_t>(words.begin() + long(at) + 1,
                                                 words.begin() + long(at + count))};
    at += count;
    auto& ops = in.operands;
    switch (opcode) {
      case op::EntryPoint:
        ++entryPoints;
        out.stages = stageOf(m, m.operand(in, 0));
        out.entryPoint = literalString(ops, 2);
        break;
      case op::Name:
        m.names[m.operand(in, 0)] = literalString(ops, 1);
        break;
      case op::ExecutionMode:
        if (m.operand(in, 1) == kModeLocalSize)
          for (size_t k = 0; k < 3; ++k) out.localSize[k] = m.operand(in, 2 + k);
        break;
      case op::Decorate: {
        Decorations& d = m.decorations[m.operand(in, 0)];
        const uint32_t which = m.operand(in, 1);
        if (which == deco::DescriptorSet) d.set = m.operand(in, 2);
        if (which == deco::Binding) d.binding = m.operand(in, 2);
        if (which == deco::SpecId) d.specId = m.operand(in, 2);
        if (which == deco::BuiltIn) d.builtIn = m.operand(in, 2);
        if (which == deco::ArrayStride) d.arrayStride = m.operand(in, 2);
        d.block = d.block || which == deco::Block;
        d.bufferBlock = d.bufferBlock || which == deco::BufferBlock;
        break;
      }
      case op::MemberDecorate: {
        const uint32_t which = m.operand(in, 2);
        if (which != deco::Offset && which != deco::MatrixStride) break;
        auto& list = which == deco::Offset ? m.memberOffsets[m.operand(in, 0)]
                                           : m.memberMatrixStrides[m.operand(in, 0)];
        const uint32_t member = m.operand(in, 1);
        if (list.size() <= member) list.resize(member + 1, 0);
        list[member] = m.operand(in, 3);
        break;
      }
      case op::Variable:
        m.variables.push_back({m.operand(in, 0), m.operand(in, 1), m.operand(in, 2)});
        break;
      case op::Constant:
      case op::SpecConstant:
      case op::ConstantComposite:
      case op::SpecConstantComposite:
        m.defs[m.operand(in, 1)] = std::move(in);
        break;
      default:
        // Types define their result id first.
        if ((opcode >= op::TypeBool && opcode <= op::TypePointer) ||
            opcode == op::TypeAccelerationStructure)
          m.defs[ops.empty() ? 0 : ops[0]] = std::move(in);
        break;
    }
  }
  if (entryPoints != 1)
    m.fail(std::to_string(entryPoints) + " entry points; the layer builds one per module");

  std::map<std::pair<uint32_t, uint32_t>, uint32_t> slots;  // (set, binding) -> variable
  for (const auto& [pointerType, id, storage] : m.variables) {
    const Instruction& pointer = m.def(pointerType);
    const uint32_t pointee = m.operand(pointer, 2);
    if (storage == kStoragePushConstant) {
      out.pushConstantBytes = std::max(out.pushConstantBytes, typeBytes(m, pointee));
      continue;
    }
    if (storage != kStorageUniformConstant && storage != kStorageUniform &&
        storage != kStorageBuffer)
      continue;
    const auto d = m.decorations.find(id);
    if (d == m.decorations.end() || d->second.binding < 0)
      m.fail("resource variable " + std::to_string(id) + " has no binding decoration");
    ReflectedBinding b = bindingOf(m, pointee, storage);
    b.set = uint32_t(std::max<int64_t>(d->second.set, 0));
    b.binding = uint32_t(d->second.binding);
    b.stages = out.stages;
    const auto [first, fresh] = slots.emplace(std::pair{b.set, b.binding}, id);
    if (!fresh)
      m.fail("set " + std::to_string(b.set) + " binding " + std::to_string(b.binding) +
             " is declared twice, by " + variableName(m, first->second) + " and by " +
             variableName(m, id) +
             " (one declared without a binding or register takes one the compiler picks)");
    out.bindings.push_back(b);
  }
  for (const auto& [id, d] : m.decorations)
    if (d.builtIn == int64_t(kBuiltInWorkgroupSize)) readWorkgroupBuiltIn(m, id, out);
  std::sort(out.bindings.begin(), out.bindings.end(), [](const auto& a, const auto& b) {
    return a.set != b.set ? a.set < b.set : a.binding < b.binding;
  });
  return out;
}

ShaderInterface mergeInterfaces(const ShaderInterface& a, const ShaderInterface& b,
                                const std::string& name) {
  ShaderInterface out = a;
  out.stages |= b.stages;
  out.pushConstantBytes = std::max(a.pushConstantBytes, b.pushConstantBytes);
  for (const auto& binding : b.bindings) {
    ReflectedBinding* same = nullptr;
    for (auto& o : out.bindings)
      if (o.set == binding.set && o.binding == binding.binding) same = &o;
    if (!same) {
      out.bindings.push_back(binding);
      continue;
    }
    if (same->type != binding.type || same->count != binding.count)
      throw ShaderInterfaceError(name + ": set " + std::to_string(binding.set) + " binding " +
                               std::to_string(binding.binding) + " is " +
                               descriptorTypeName(same->type) + " in one stage and " +
                               descriptorTypeName(binding.type) + " in another");
    same->stages |= binding.stages;
  }
  std::sort(out.bindings.begin(), out.bindings.end(), [](const auto& x, const auto& y) {
    return x.set != y.set ? x.set < y.set : x.binding < y.binding;
  });
  return out;
}

const char* descriptorTypeName(VkDescriptorType type) {
  switch (type) {
    case VK_DESCRIPTOR_TYPE_SAMPLER:
      return "sampler";
    case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER:
      return "combined image sampler";
    case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE:
      return "sampled image";
    case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE:
      return "storage image";
    case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER:
      return "uniform texel buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER:
      return "storage texel buffer";
    case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER:
      return "uniform buffer";
    case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER:
      return "storage buffer";
    case VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT:
      return "input attachment";
    case VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR:
      return "acceleration structure";
    default:
      return "unknown descriptor";
  }
}

}  // namespace taa::vk

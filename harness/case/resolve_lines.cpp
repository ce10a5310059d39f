#include "case/resolve_lines.h"

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <set>
#include <spirv-tools/optimizer.hpp>
#include <unordered_map>

#include "api/device.h"
#include "core/errors.h"
#include "spec/taa_spec.h"  // the settings table: TAA_SPEC_HAS_HISTORY

namespace taa::cases {

namespace {

using Line = std::pair<std::string, int>;

// The opcodes the instrumentation reads and writes (SPIR-V specification, section 3.49).
enum Op : uint32_t {
  kOpString = 7,
  kOpLine = 8,
  kOpEntryPoint = 15,
  kOpTypeVoid = 19,
  kOpTypeInt = 21,
  kOpTypeStruct = 30,
  kOpTypePointer = 32,
  kOpConstant = 43,
  kOpFunction = 54,
  kOpFunctionEnd = 56,
  kOpVariable = 59,
  kOpStore = 62,
  kOpAccessChain = 65,
  kOpDecorate = 71,
  kOpMemberDecorate = 72,
  kOpPhi = 245,
  kOpLoopMerge = 246,
  kOpSelectionMerge = 247,
  kOpLabel = 248,
  kOpNoLine = 317,
};
constexpr uint32_t kStorageBuffer = 12;
constexpr uint32_t kBlock = 2, kBinding = 33, kDescriptorSet = 34, kOffset = 35;
constexpr size_t kHeaderWords = 5;

using Instruction = std::vector<uint32_t>;

std::vector<Instruction> instructions(const std::vector<uint32_t>& spirv) {
  std::vector<Instruction> out;
  for (size_t at = kHeaderWords; at < spirv.size();) {
    const uint32_t count = spirv[at] >> 16;
    if (count == 0 || at + count > spirv.size())
      throw EnvironmentError("taa_resolve.comp.lines.spv: a truncated instruction; rebuild the shaders");
    out.emplace_back(spirv.begin() + long(at), spirv.begin() + long(at + count));
    at += count;
  }
  return out;
}

uint32_t opcode(const Instruction& i) { return i[0] & 0xffff; }
Instruction make(uint32_t op, std::initializer_list<uint32_t> operands) {
  Instruction out = {(uint32_t(operands.size() + 1) << 16) | op};
  out.insert(out.end(), operands.begin(), operands.end());
  return out;
}

// OpString's literal: UTF-8, nul-terminated, packed four bytes a word (little end first).
std::string literal(const Instruction& i, size_t from) {
  std::string out;
  for (size_t w = from; w < i.size(); ++w)
    for (int b = 0; b < 4; ++b) {
      const char c = char((i[w] >> (8 * b)) & 0xff);
      if (c == 0) return out;
      out += c;
    }
  return out;
}

// The resolve with a marker on every line: before the first instruction a line's OpLine
// annotates, a store of the line's number into a storage buffer of its own. A store to a
// buffer is never dead code, so a marker survives folding and dead-code removal exactly when
// its block is reachable: a line that is only a condition folded away still counts as run.
// (Workgroup memory would not do: dead-code removal drops stores nothing reads there.)
struct Instrumented {
  std::vector<uint32_t> spirv;
  uint32_t marker = 0;      // the buffer variable the markers store to
  std::vector<Line> lines;  // marker value -> line (a line has a marker in each of its blocks)
};

Instrumented instrument(const std::vector<uint32_t>& spirv) {
  auto code = instructions(spirv);
  uint32_t bound = spirv[3];
  Instrumented out;
  std::map<uint32_t, std::string> files;
  uint32_t uintType = 0;
  for (const auto& i : code) {
    if (opcode(i) == kOpString) files[i[1]] = literal(i, 2);
    if (opcode(i) == kOpTypeInt && i.size() == 4 && i[2] == 32 && i[3] == 0) uintType = i[1];
  }
  std::vector<Instruction> globals;  // declared just before the first function
  if (!uintType) globals.push_back(make(kOpTypeInt, {uintType = bound++, 32, 0}));
  const uint32_t block = bound++, blockPointer = bound++, uintPointer = bound++, zero = bound++;
  out.marker = bound++;
  globals.push_back(make(kOpTypeStruct, {block, uintType}));
  globals.push_back(make(kOpTypePointer, {blockPointer, kStorageBuffer, block}));
  globals.push_back(make(kOpTypePointer, {uintPointer, kStorageBuffer, uintType}));
  globals.push_back(make(kOpConstant, {uintType, zero, 0}));
  globals.push_back(make(kOpVariable, {blockPointer, out.marker, kStorageBuffer}));
  // A set no resolve input uses; the module is only analysed, never bound.
  const std::vector<Instruction> decorations = {
      make(kOpDecorate, {block, kBlock}), make(kOpMemberDecorate, {block, 0, kOffset, 0}),
      make(kOpDecorate, {out.marker, kDescriptorSet, 7}), make(kOpDecorate, {out.marker, kBinding, 0})};

  // One marker per line and block: a line's condition and the statement it guards are two
  // blocks, so "the condition runs, the statement never" shows.
  std::map<std::pair<Line, uint32_t>, uint32_t> constantOf;
  std::vector<Instruction> body;
  bool inFunction = false, inBlock = false;
  uint32_t label = 0;
  std::optional<Line> pending;
  for (auto& i : code) {
    const uint32_t op = opcode(i);
    if (op == kOpFunction) inFunction = true;
    if (op == kOpFunctionEnd) inFunction = inBlock = false;
    if (op == kOpLabel) {
      inBlock = true;
      label = i[1];
      pending.reset();  // an OpLine right before a label annotates nothing
    }
    if (op == kOpEntryPoint) {  // SPIR-V 1.4 on: every global an entry point uses is in its interface
      i.push_back(out.marker);
      i[0] += 1u << 16;
    }
    if (inFunction && op == kOpLine) pending = Line{files.count(i[1]) ? files[i[1]] : "?", int(i[2])};
    const bool annotated = op != kOpLine && op != kOpNoLine && op != kOpPhi && op != kOpVariable && op != kOpLabel;
    if (pending && inBlock && annotated) {
      auto [it, added] = constantOf.try_emplace({*pending, label}, 0);
      if (added) {
        it->second = bound++;
        globals.push_back(make(kOpConstant, {uintType, it->second, uint32_t(out.lines.size())}));
        out.lines.push_back(*pending);
      }
      // Before the instruction, and so before a merge instruction, which must stay next to its branch.
      const uint32_t at = bound++;
      body.push_back(make(kOpAccessChain, {uintPointer, at, out.marker, zero}));
      body.push_back(make(kOpStore, {at, it->second}));
      pending.reset();
    }
    body.push_back(std::move(i));
  }
  // Globals before the first OpFunction.
  std::vector<Instruction> all;
  bool placed = false, decorated = false;
  for (auto& i : body) {
    // Annotations come before the first type.
    if (!decorated && opcode(i) >= kOpTypeVoid && opcode(i) <= kOpTypePointer) {
      all.insert(all.end(), decorations.begin(), decorations.end());
      decorated = true;
    }
    if (!placed && opcode(i) == kOpFunction) {
      for (auto& g : globals) all.push_back(std::move(g));
      placed = true;
    }
    all.push_back(std::move(i));
  }
  out.spirv.assign(spirv.begin(), spirv.begin() + kHeaderWords);
  out.spirv[3] = bound;
  for (const auto& i : all) out.spirv.insert(out.spirv.end(), i.begin(), i.end());
  return out;
}

// The markers whose stores survive: the lines whose blocks the specialization reaches.
// Folding and dead-code passes only (nothing that moves code between lines). Three rounds: a
// folded branch exposes further constants to the next.
std::set<int> reachedMarkers(const Instrumented& module,
                             const std::unordered_map<uint32_t, std::vector<uint32_t>>* values) {
  spvtools::Optimizer opt(SPV_ENV_VULKAN_1_2);
  std::string problem;
  opt.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* m) {
    if (level <= SPV_MSG_ERROR && problem.empty()) problem = m;
  });
  if (values) {
    opt.RegisterPass(spvtools::CreateSetSpecConstantDefaultValuePass(*values));
    opt.RegisterPass(spvtools::CreateFreezeSpecConstantValuePass());
    // glslang writes a comparison of constants alone (kResolve == RESOLVE_BASIC) as a global
    // OpSpecConstantOp, which only this pass folds.
    opt.RegisterPass(spvtools::CreateFoldSpecConstantOpAndCompositePass());
  }
  opt.RegisterPass(spvtools::CreateMergeReturnPass());
  opt.RegisterPass(spvtools::CreateInlineExhaustivePass());
  opt.RegisterPass(spvtools::CreateEliminateDeadFunctionsPass());
  opt.RegisterPass(spvtools::CreatePrivateToLocalPass());
  for (int round = 0; round < 3; ++round) {
    opt.RegisterPass(spvtools::CreateScalarReplacementPass(0));
    opt.RegisterPass(spvtools::CreateLocalAccessChainConvertPass());
    opt.RegisterPass(spvtools::CreateLocalSingleBlockLoadStoreElimPass());
    opt.RegisterPass(spvtools::CreateLocalSingleStoreElimPass());
    opt.RegisterPass(spvtools::CreateSSARewritePass());
    opt.RegisterPass(spvtools::CreateCCPPass());
    opt.RegisterPass(spvtools::CreateSimplificationPass());
    opt.RegisterPass(spvtools::CreateDeadInsertElimPass());
    opt.RegisterPass(spvtools::CreateCopyPropagateArraysPass());
    opt.RegisterPass(spvtools::CreateDeadBranchElimPass());
    opt.RegisterPass(spvtools::CreateBlockMergePass());
    opt.RegisterPass(spvtools::CreateAggressiveDCEPass());
  }
  std::vector<uint32_t> optimized;
  spvtools::OptimizerOptions options;
  options.set_run_validator(false);  // glslang's output plus the markers; the renderer validates its own
  if (!opt.Run(module.spirv.data(), module.spirv.size(), &optimized, options))
    throw EnvironmentError("taa_resolve.comp.lines.spv: SPIRV-Tools could not specialize it (" +
                           (problem.empty() ? std::string("no message") : problem) + ")");
  std::map<uint32_t, uint32_t> constants;  // id -> value
  std::set<uint32_t> chains, stored;        // access chains into the marker buffer, stored values
  for (const auto& i : instructions(optimized)) {
    if (opcode(i) == kOpConstant && i.size() == 4) constants[i[2]] = i[3];
    if (opcode(i) == kOpAccessChain && i.size() >= 4 && i[3] == module.marker) chains.insert(i[2]);
    if (opcode(i) == kOpStore && i.size() >= 3 && chains.count(i[1])) stored.insert(i[2]);
  }
  std::set<int> out;
  for (uint32_t id : stored)
    if (constants.count(id) && constants[id] < module.lines.size()) out.insert(int(constants[id]));
  return out;
}

}  // namespace

std::vector<SourceLine> resolveLineCoverage(const std::vector<uint32_t>& spirv,
                                            const std::map<std::string, std::map<int, int>>& constants) {
  if (spirv.size() < kHeaderWords || spirv[0] != 0x07230203u)
    throw EnvironmentError("taa_resolve.comp.lines.spv is not SPIR-V; rebuild the shaders");
  const Instrumented module = instrument(spirv);
  std::map<int, std::vector<std::string>> rows;  // marker -> cases
  for (int m : reachedMarkers(module, nullptr)) rows[m];
  // Cases that run the same pipelines share one specialization (most differ in floats only).
  std::map<std::map<int, int>, std::set<int>> byConstants;
  for (const auto& [name, traced] : constants) {
    auto [it, added] = byConstants.try_emplace(traced);
    if (added) {
      // A bool constant's bit pattern is 0 or 1, as the trace writes it.
      std::unordered_map<uint32_t, std::vector<uint32_t>> values;
      for (const auto& [id, value] : traced) values[uint32_t(id)] = {uint32_t(value)};
      it->second = reachedMarkers(module, &values);
      values[TAA_SPEC_HAS_HISTORY] = {0u};
      for (int m : reachedMarkers(module, &values)) it->second.insert(m);
    }
    for (int m : it->second)
      if (const auto row = rows.find(m); row != rows.end()) row->second.push_back(name);
  }
  std::map<Line, SourceLine> byLine;
  for (auto& [m, cases] : rows) {
    const Line& line = module.lines[size_t(m)];
    SourceLine& out = byLine.try_emplace(line, SourceLine{line.first, line.second, {}, false}).first->second;
    if (cases.empty()) out.partly = true;
    out.cases.insert(out.cases.end(), cases.begin(), cases.end());
  }
  std::vector<SourceLine> out;
  for (auto& [line, row] : byLine) {
    std::sort(row.cases.begin(), row.cases.end());
    row.cases.erase(std::unique(row.cases.begin(), row.cases.end()), row.cases.end());
    if (row.cases.empty()) row.partly = false;  // not run at all
    out.push_back(std::move(row));
  }
  return out;
}

std::vector<uint32_t> loadResolveWithLines() {
  return shaderFolderWords("taa_resolve.comp.lines.spv");
}

}  // namespace taa::cases

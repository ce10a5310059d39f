#include "user/entry_checks.h"

#include <glslang/MachineIndependent/localintermediate.h>

namespace taa::user {

namespace {

// The thread ids a compute entry may take (SV_DispatchThreadID, SV_GroupID, SV_GroupThreadID,
// SV_GroupIndex, and their GLSL and subgroup counterparts).
bool computeInput(glslang::TBuiltInVariable b) {
  switch (b) {
    case glslang::EbvNumWorkGroups:
    case glslang::EbvWorkGroupId:
    case glslang::EbvLocalInvocationId:
    case glslang::EbvGlobalInvocationId:
    case glslang::EbvLocalInvocationIndex:
    case glslang::EbvNumSubgroups:
    case glslang::EbvSubgroupID:
    case glslang::EbvSubGroupSize:
    case glslang::EbvSubGroupInvocation:
    case glslang::EbvSubgroupSize2:
    case glslang::EbvSubgroupInvocation2:
      return true;
    default:
      return false;
  }
}

// The function definition the user wrote: HLSL's is "@ENTRY(...)" once glslang wrapped it,
// GLSL's "main(".
const glslang::TIntermAggregate* entryFunction(const glslang::TIntermediate& p,
                                               const std::string& entry) {
  const auto* root = p.getTreeRoot() ? p.getTreeRoot()->getAsAggregate() : nullptr;
  if (!root) return nullptr;
  for (const std::string& prefix : {"@" + entry + "(", entry + "("})
    for (const auto* node : root->getSequence()) {
      const auto* f = node->getAsAggregate();
      if (f && f->getOp() == glslang::EOpFunction && f->getName().rfind(prefix.c_str(), 0) == 0)
        return f;
    }
  return nullptr;
}

}  // namespace

std::string entryPointProblem(const glslang::TIntermediate& p, const std::string& file,
                              const std::string& entry) {
  const auto* f = entryFunction(p, entry);
  std::string at = file;
  if (f) {
    const glslang::TSourceLoc& loc = f->getLoc();
    at = (loc.getFilename() ? std::string(loc.getFilename()) : file) + ":" +
         std::to_string(loc.line);
  }
  const std::string size = std::to_string(p.getLocalSize(0)) + ", " +
                           std::to_string(p.getLocalSize(1)) + ", " +
                           std::to_string(p.getLocalSize(2));
  for (int i = 0; i < 3; ++i)
    if (p.getLocalSize(i) == 0)
      return at + ": the entry point " + entry + " declares a workgroup of (" + size +
             "), with a zero; every dimension is at least 1 ([numthreads(8, 8, 1)], "
             "local_size_x = 8)";
  const auto* root = p.getTreeRoot() ? p.getTreeRoot()->getAsAggregate() : nullptr;
  if (!root || root->getSequence().empty()) return "";
  const auto* objects = root->getSequence().back()->getAsAggregate();
  if (!objects || objects->getOp() != glslang::EOpLinkerObjects) return "";
  const std::string ids =
      "; a resolve's entry takes only thread ids (SV_DispatchThreadID, SV_GroupID, "
      "SV_GroupThreadID, SV_GroupIndex) and returns void";
  for (const auto* node : objects->getSequence()) {
    const auto* sym = node->getAsSymbolNode();
    if (!sym) continue;
    const glslang::TQualifier& q = sym->getQualifier();
    const std::string name = sym->getName().c_str();
    if (q.isPipeOutput())
      return at + ": the entry point " + entry +
             (name == "@entryPointOutput" ? std::string(" returns a value")
                                          : " has an output parameter '" + name + "'") +
             ", which a compute shader has nowhere to put (SV_Target is a pixel shader's)" + ids;
    if (!q.isPipeInput()) continue;
    if (q.builtIn == glslang::EbvNone)
      return at + ": the entry point " + entry + "'s parameter '" + name +
             "' has no compute semantic (none, one HLSL does not know, or another stage's such as "
             "SV_Position)" +
             ids;
    if (!computeInput(q.builtIn))
      return at + ": the entry point " + entry + "'s parameter '" + name + "' is the built-in " +
             glslang::GetBuiltInVariableString(q.builtIn) +
             ", which a compute shader does not have (SV_Position is a pixel shader's)" + ids;
  }
  return "";
}

}  // namespace taa::user

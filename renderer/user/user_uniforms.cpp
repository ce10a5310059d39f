#include "user/user_uniforms.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace taa::user {

std::string scalarBits(ParamType t, const spec::NumberOrBool& v, uint32_t& bits,
                       bool boolAsNumber) {
  const double n = v.number;
  const bool whole = std::floor(n) == n;
  if (v.isBool && t != ParamType::Bool && !(boolAsNumber && t != ParamType::Float))
    return std::string("give a number, not true or false, for a ") + paramTypeName(t);
  switch (t) {
    case ParamType::Bool:
      if (n != 0.0 && n != 1.0) return "a bool takes true or false (or 1 or 0)";
      bits = n != 0.0;
      return {};
    case ParamType::Int:
      if (!whole || n < -2147483648.0 || n > 2147483647.0)
        return "an int takes a whole number from -2147483648 to 2147483647";
      bits = uint32_t(int32_t(int64_t(n)));
      return {};
    case ParamType::Uint:
      if (!whole || n < 0.0 || n > 4294967295.0)
        return "a uint takes a whole number from 0 to 4294967295";
      bits = uint32_t(int64_t(n));
      return {};
    case ParamType::Float: {
      if (std::fabs(n) > 3.4028234663852886e38) return "a float takes a number within float range";
      const float f = float(n);
      std::memcpy(&bits, &f, 4);
      return {};
    }
  }
  return "unknown type";
}

namespace {

// Component k of a member's value (k < m.count()), as one number.
spec::NumberOrBool component(const spec::NumberOrBool& v, uint32_t k) {
  if (v.list.empty()) return v;
  return {v.list[k], false, {}};
}

// Where component k (column k / rows, row k % rows) lies in the block.
uint32_t componentOffset(const UserUniform& m, uint32_t k) {
  const uint32_t column = k / m.rows, row = k % m.rows;
  if (m.columns == 1) return m.offset + 4 * row;
  return m.rowMajor ? m.offset + row * m.matrixStride + 4 * column
                    : m.offset + column * m.matrixStride + 4 * row;
}

const spec::ShaderParam* given(const spec::TaaSpec& taa, const std::string& name) {
  for (const auto& p : taa.shader_params)
    if (p.name == name) return &p;
  return nullptr;
}

std::string numberText(double d) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), d);
  return std::string(buf, r.ptr);
}

}  // namespace

std::string uniformValueProblem(const UserUniform& m, const spec::NumberOrBool& v) {
  const std::string what = m.name + " is a " + m.typeName() + " uniform";
  if (!m.supported)
    return what +
           ", which shader_params cannot set (only scalars, vectors and matrices of 32-bit "
           "numbers); make it static or set it in the shader";
  const uint32_t n = m.count();
  const size_t gave = v.list.empty() ? 1 : v.list.size();
  if (gave != n)
    return what + "; give " +
           (n == 1 ? std::string("one number") : "a list of " + std::to_string(n) + " numbers") +
           ", not " + (v.list.empty() ? std::string("one") : std::to_string(gave)) +
           (m.columns > 1 ? " (in the order the shader indexes it: m[0][0], m[0][1], ...)" : "");
  for (uint32_t k = 0; k < n; ++k) {
    uint32_t bits = 0;
    if (const std::string why = scalarBits(m.type, component(v, k), bits, true); !why.empty())
      return what + (n > 1 ? " (number " + std::to_string(k) + ")" : std::string()) + "; " + why;
  }
  return {};
}

std::vector<uint8_t> userUniformBytes(const spec::TaaSpec& taa, const UserInterface& u) {
  std::vector<uint8_t> out(u.uniformBytes, 0);
  for (const UserUniform& m : u.uniforms) {
    const spec::ShaderParam* p = given(taa, m.name);
    if (!p || !uniformValueProblem(m, p->value).empty()) continue;
    for (uint32_t k = 0; k < m.count(); ++k) {
      uint32_t bits = 0;
      scalarBits(m.type, component(p->value, k), bits, true);
      const uint32_t at = componentOffset(m, k);
      if (uint64_t(at) + 4 <= out.size()) std::memcpy(out.data() + at, &bits, 4);
    }
  }
  return out;
}

std::string describeUserUniforms(const spec::TaaSpec& taa, const UserInterface& u) {
  if (u.uniformBytes == 0) return "";
  std::string set, unset;
  for (const UserUniform& m : u.uniforms) {
    const spec::ShaderParam* p = given(taa, m.name);
    if (!p) {
      unset += (unset.empty() ? "" : ", ") + m.name + " (" + m.typeName() + ")";
      continue;
    }
    std::string value;
    if (p->value.list.empty()) {
      value = p->value.isBool ? (p->value.number != 0.0 ? "true" : "false")
                              : numberText(p->value.number);
    } else {
      for (const double d : p->value.list) value += (value.empty() ? "[" : ", ") + numberText(d);
      value += "]";
    }
    set += (set.empty() ? "" : ", ") + m.name + "=" + value + " (" + m.typeName() + ")";
  }
  return "loose uniforms " + (u.uniformBlock.empty() ? std::string("block") : u.uniformBlock) +
         " (" + std::to_string(u.uniformBytes) + " bytes): " + (set.empty() ? "none set" : set) +
         (unset.empty() ? "" : "; zero, not set: " + unset);
}

}  // namespace taa::user

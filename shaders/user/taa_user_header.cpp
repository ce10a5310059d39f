// Writes taa_user.h from its template (taa_user.h.in) and the resolve input table
// (common/resolve_inputs.h): the inputs a user's shader may declare, their TAA_USE_* guards
// and documentation, and the bindings of its own targets. Run by the build:
//   taa_user_header TEMPLATE OUTPUT
#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "common/resolve_inputs.h"

namespace {

struct UserInput {
  std::string name, stype, macro, doc;
  int binding;
};

#define TAA_USER_ROW(cxx, log, glsl, bind, stype, fmt, filter, src, uname, umacro, ubind, udoc) \
  {#uname, #stype, #umacro, udoc, ubind},
const UserInput kRows[] = {TAA_RESOLVE_INPUTS(TAA_USER_ROW)};
#undef TAA_USER_ROW

bool always(const UserInput& r) {
  return r.macro == "TAA_USER_ALWAYS";
}

// "//   <lead><doc>", the doc wrapped under itself within 94 columns.
std::string docLines(const std::string& lead, const std::string& doc) {
  const std::string indent = "//   " + std::string(lead.size(), ' ');
  std::string out = "//   " + lead, word;
  size_t column = out.size();
  std::istringstream words(doc);
  bool first = true;
  while (words >> word) {
    if (!first && column + 1 + word.size() > 94) {
      out += "\n" + indent;
      column = indent.size();
      first = true;
    }
    out += (first ? "" : " ") + word;
    column += (first ? 0 : 1) + word.size();
    first = false;
  }
  return out;
}

std::string pad(std::string s, size_t width) {
  if (s.size() < width) s.resize(width, ' ');
  return s + " ";
}

std::string substitute(std::string text, const std::string& marker, const std::string& value) {
  const std::string key = "@" + marker + "@";
  for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
    text.replace(at, key.size(), value);
  return text;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: taa_user_header TEMPLATE OUTPUT\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in) {
    std::cerr << "taa_user_header: cannot read " << argv[1] << "\n";
    return 3;
  }
  std::vector<UserInput> rows;
  for (const UserInput& r : kRows)
    if (r.binding >= 0) rows.push_back(r);
  std::sort(rows.begin(), rows.end(),
            [](const UserInput& a, const UserInput& b) { return a.binding < b.binding; });

  // Columns as wide as their longest entry and one more (the template's taa_output line).
  size_t nameWidth = 0, macroWidth = 0;
  for (const UserInput& r : rows) {
    nameWidth = std::max(nameWidth, r.name.size() + 1);
    if (!always(r)) macroWidth = std::max(macroWidth, r.macro.size() + 1);
  }
  std::string alwaysDocs, macroDocs, declarations;
  for (const UserInput& r : rows) {
    const std::string decl = "layout(set = 0, binding = " + std::to_string(r.binding) +
                             ") uniform " + r.stype + " " + r.name + ";\n";
    if (always(r)) {
      alwaysDocs += (alwaysDocs.empty() ? "" : "\n") + docLines(pad(r.name, nameWidth), r.doc);
      declarations += decl;
    } else {
      macroDocs += (macroDocs.empty() ? "" : "\n") +
                   docLines(pad(r.macro, macroWidth) + pad(r.name, nameWidth), r.doc);
      declarations += "#ifdef " + r.macro + "\n" + decl + "#endif\n";
    }
  }
  if (!declarations.empty()) declarations.pop_back();  // the template's line ends it

  std::string text = buffer.str();
  text = substitute(text, "TAA_USER_ALWAYS_DOCS", alwaysDocs);
  text = substitute(text, "TAA_USER_MACRO_DOCS", macroDocs);
  text = substitute(text, "TAA_USER_INPUT_DECLARATIONS", declarations);
  text = substitute(text, "TAA_USER_BINDING_FRAME", std::to_string(TAA_USER_BINDING_FRAME));
  text = substitute(text, "TAA_USER_BINDING_OUTPUT", std::to_string(TAA_USER_BINDING_OUTPUT));
  text = substitute(text, "TAA_USER_BINDING_HISTORY0", std::to_string(TAA_USER_BINDING_HISTORY0));
  text = substitute(text, "TAA_USER_BINDING_HISTORY0_OUT",
                    std::to_string(TAA_USER_BINDING_HISTORY0_OUT));
  text = substitute(text, "TAA_USER_BINDING_HISTORY1", std::to_string(TAA_USER_BINDING_HISTORY1));
  text = substitute(text, "TAA_USER_BINDING_HISTORY1_OUT",
                    std::to_string(TAA_USER_BINDING_HISTORY1_OUT));
  if (text.find('@') != std::string::npos) {
    std::cerr << "taa_user_header: " << argv[1] << " has a marker this tool does not fill\n";
    return 2;
  }
  std::ofstream out(argv[2], std::ios::binary);
  out << text;
  out.close();
  if (!out) {
    std::cerr << "taa_user_header: cannot write " << argv[2] << "\n";
    return 3;
  }
  return 0;
}

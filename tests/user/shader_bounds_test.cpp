// Hostile user shaders, one generator per class: what one shader may cost before glslang and
// the driver (expression depth, macro and include bombs, private and shared memory) and what
// it may declare (taa_user.h's interface only). Each is refused with a message naming the
// shader and the bound, from a compile in a child process that cannot take the harness down.
#include "user/shader_bounds.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <time.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>

#include "support/shader_folder.h"
#include "user/compile_sandbox.h"
#include "user/glsl_compiler.h"
#include "user/user_interface.h"

namespace taa::user {
namespace {

namespace fs = std::filesystem;

class ShaderBoundsTest : public test::ShaderFolderTest {
 protected:
  // A resolve that includes taa_user.h, with `decl` before main and `value` stored.
  fs::path resolve(const std::string& name, const std::string& decl,
                   const std::string& value = "taa_color_at(p)") {
    return write(name, "#version 450\n#include \"taa_user.h\"\n" + decl +
                           "\nvoid main() {\n  ivec2 p;\n  if (!taa_pixel(p)) return;\n"
                           "  imageStore(taa_output, p, vec4(" +
                           value + ", 1.0));\n}\n");
  }
  // The message of compiling and reflecting `file`, which must be refused.
  std::string refusal(const fs::path& file) {
    try {
      const CompiledShader c = compileComputeShader(file, options_);
      reflectUserInterface(c.spirv, file.string());
    } catch (const ShaderCompileError& e) {
      return e.what();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    ADD_FAILURE() << file << " was accepted";
    return {};
  }
  void accepted(const fs::path& file) {
    const CompiledShader c = compileComputeShader(file, options_);
    EXPECT_NO_THROW(reflectUserInterface(c.spirv, file.string()));
  }
};

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

std::string sumOf(int terms) {
  std::string s = "x";
  for (int i = 1; i < terms; ++i) s += "+x";
  return s;
}

TEST_F(ShaderBoundsTest, ExpressionDeeperThanTheBoundIsRefusedBeforeGlslangRecursesOverIt) {
  // 20,000 terms overflow glslang's 8 MiB stack (SIGSEGV before this bound existed); the
  // issue's 1 MiB shader had 520,000.
  for (int terms : {kMaxExpressionDepth + 2, 20000, 200000}) {
    SCOPED_TRACE(terms);
    const auto file =
        resolve("deep.comp", "float f(float x) { return " + sumOf(terms) + "; }", "vec3(f(1.0))");
    const std::string msg = refusal(file);
    EXPECT_HAS(msg, file.string() + ":3: a statement nests");
    EXPECT_HAS(msg, "over the bound of " + std::to_string(kMaxExpressionDepth));
  }
  // Brackets count as levels too.
  const std::string nested = std::string(kMaxExpressionDepth + 1, '(') + "x" +
                             std::string(kMaxExpressionDepth + 1, ')');
  EXPECT_HAS(refusal(resolve("parens.comp", "float f(float x) { return " + nested + "; }",
                             "vec3(f(1.0))")),
             "a statement nests");
  // A long but shallow expression and a large initializer list are fine.
  accepted(resolve("ok.comp", "float f(float x) { return " + sumOf(4000) + "; }", "vec3(f(1.0))"));
  std::string table = "const float kTable[256] = float[256](0.0";
  for (int i = 1; i < 256; ++i) table += ", " + std::to_string(i % 7) + ".0";
  accepted(resolve("table.comp", table + ");", "vec3(kTable[p.x & 255])"));
}

TEST_F(ShaderBoundsTest, ExpressionDepthCountsOperatorsAndBracketsPerStatement) {
  EXPECT_EQ(expressionDepthProblem("float a = " + sumOf(kMaxExpressionDepth) + ";", "f"), "");
  EXPECT_HAS(expressionDepthProblem("float a = 1;\n#line 40 \"h.glsl\"\nfloat b = " +
                                        sumOf(kMaxExpressionDepth + 2) + ";",
                                    "f"),
             "h.glsl:40: a statement nests");
  // Arguments are siblings, not a chain: a call with many arguments is shallow.
  std::string call = "f(x";
  for (int i = 0; i < kMaxExpressionDepth * 2; ++i) call += ", x";
  EXPECT_EQ(expressionDepthProblem("y = " + call + ");", "f"), "");
  // But the deepest of them counts: a group a comma ends keeps its brackets' depth.
  const std::string deep = std::string(kMaxExpressionDepth + 1, '(') + "x" +
                           std::string(kMaxExpressionDepth + 1, ')');
  EXPECT_HAS(expressionDepthProblem("y = f(" + deep + ", x);", "f"), "f:1: a statement nests");
  EXPECT_HAS(expressionDepthProblem("y = f(x, " + deep + ");", "f"), "f:1: a statement nests");
  // An unterminated statement is still measured.
  EXPECT_NE(expressionDepthProblem("y = " + sumOf(kMaxExpressionDepth + 2), "f"), "");
}

TEST_F(ShaderBoundsTest, MacroBombIsStoppedByThePreprocessorsCpuBound) {
  // 30 doublings: 2^30 tokens from 600 bytes (the bomb: 9 s and 2.2 GB, then SIGSEGV).
  // A quarter of a second stops it as the shipped 3 s would, twelve times sooner.
  options_.preprocessCpu = std::chrono::milliseconds(250);
  std::string defs = "#define A0 x\n";
  for (int i = 1; i <= 30; ++i)
    defs += "#define A" + std::to_string(i) + " (A" + std::to_string(i - 1) + "+A" +
            std::to_string(i - 1) + ")\n";
  const auto file = resolve("bomb.comp", defs + "float f(float x) { return A30; }", "vec3(f(1.0))");
  const std::string msg = refusal(file);
  EXPECT_HAS(msg, "bomb.comp: its preprocessor ran more than 0.25 s of CPU");
  // Fewer doublings of a long name expand past the preprocessed-size bound instead, in a
  // fraction of the shipped CPU bound: 2^15 names of 200 letters make 6.6 MB from 130k tokens,
  // where 2^20 one-letter names (4.2M tokens) took over 3 s of CPU under ASan on a busy CI machine.
  options_.preprocessCpu = kPreprocessCpu;
  const std::string name(200, 'x');
  std::string small = "#define B0 " + name + "\n";
  for (int i = 1; i <= 15; ++i)
    small += "#define B" + std::to_string(i) + " (B" + std::to_string(i - 1) + "+B" +
             std::to_string(i - 1) + ")\n";
  const std::string big = refusal(
      resolve("big.comp", small + "float f(float " + name + ") { return B15; }", "vec3(f(1.0))"));
  EXPECT_TRUE(big.find("after macros and includes, over the bound") != std::string::npos ||
              big.find("a statement nests") != std::string::npos)
      << big;
}

TEST_F(ShaderBoundsTest, IncludeBombsStopAtTheDepthAndCountBounds) {
  // Including itself twice: depth 32 alone would allow 2^32 includes.
  write("self.h", "#include \"self.h\"\n#include \"self.h\"\n");
  const std::string self = refusal(resolve("self.comp", "#include \"self.h\""));
  EXPECT_HAS(self, "includes nest deeper than " + std::to_string(kMaxIncludeDepth));
  // A guarded header included more often than the count bound, flat.
  write("guarded.h", "#ifndef GUARDED_H\n#define GUARDED_H\nconst float kG = 1.0;\n#endif\n");
  std::string many;
  for (size_t i = 0; i <= kMaxIncludes; ++i) many += "#include \"guarded.h\"\n";
  const std::string count = refusal(resolve("many.comp", many));
  EXPECT_HAS(count, "resolves more than " + std::to_string(kMaxIncludes) + " #include");
  // One glslang complaint per refused include would repeat the reason a thousand times.
  EXPECT_EQ(count.find("Could not process include"), std::string::npos) << count;
}

TEST_F(ShaderBoundsTest, IncludeLeavingTheFolderSaysOnlyThatItLeaves) {
  // Whether a file outside exists must not show: both refusals read the same.
  std::ofstream(dir_ / "secret.glsl") << "vec3 secret() { return vec3(1); }\n";
  fs::create_symlink(dir_ / "secret.glsl", dir_ / "src/link.glsl");
  fs::create_symlink(dir_ / "nothing-here.glsl", dir_ / "src/dangling.glsl");
  for (const char* inc : {"../secret.glsl", "../nothing-here.glsl", "/etc/passwd", "link.glsl",
                          "dangling.glsl"}) {
    SCOPED_TRACE(inc);
    const std::string msg = refusal(resolve("escape.comp", std::string("#include \"") + inc + "\""));
    EXPECT_HAS(msg, std::string("#include \"") + inc + "\" leads outside the shader's folder");
    EXPECT_EQ(msg.find("secret.glsl'"), std::string::npos) << msg;
    EXPECT_EQ(msg.find(dir_.string() + "/secret"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("not found"), std::string::npos) << msg;
  }
}

TEST_F(ShaderBoundsTest, PrivateAndSharedMemoryAreBoundedFromTheSpirv) {
  // The private array compiled and then hung lavapipe past 60 s at 3.6 GB.
  const std::string priv = refusal(resolve(
      "private.comp",
      "float g(ivec2 p) { float a[4000000]; a[p.x] = 1.0; return a[p.y]; }", "vec3(g(p))"));
  EXPECT_HAS(priv, "bytes of private memory per invocation, over the bound of " +
                       std::to_string(kMaxPrivateBytes));
  EXPECT_HAS(refusal(resolve("global.comp", "float gPriv[8192];", "vec3(gPriv[p.x])")),
             "of private memory per invocation");
  const std::string shared =
      refusal(resolve("shared.comp", "shared vec4 tile[262144];", "tile[p.x].rgb"));
  EXPECT_HAS(shared, "4194304 bytes, over the bound of " + std::to_string(kMaxSharedBytes));
  // A specialization constant that sizes the array is evaluated, at its default here.
  EXPECT_HAS(refusal(resolve("spec.comp",
                             "layout(constant_id = 0) const int N = 8;\n"
                             "shared vec4 tile[N * 1024];",
                             "tile[p.x].rgb")),
             "131072 bytes");
  // Lookup tables: lavapipe's compile is quadratic in their size.
  auto table = [](int n) {
    std::string t = "const float kT[" + std::to_string(n) + "] = float[](0.0";
    for (int i = 1; i < n; ++i) t += ", " + std::to_string(i % 5) + ".0";
    return t + ");";
  };
  EXPECT_HAS(refusal(resolve("t4096.comp", table(4096), "vec3(kT[p.x])")),
             "constant arrays hold 4096 numbers, over the bound of " +
                 std::to_string(kMaxConstantArrayNumbers));
  accepted(resolve("t1024.comp", table(int(kMaxConstantArrayNumbers)), "vec3(kT[p.x])"));
  // What a resolve needs passes: a 5x5 neighbourhood and a 10x10 tile.
  accepted(resolve("fine.comp", "shared vec4 tile[100];\nvec3 nb[25];",
                   "tile[p.x % 100].rgb + nb[p.y % 25]"));
}

TEST_F(ShaderBoundsTest, SpecializedArrayLengthsUseTheCasesValues) {
  const auto file = resolve("n.comp",
                            "layout(constant_id = 3) const int N = 4;\nshared vec4 tile[N];",
                            "tile[p.x % N].rgb");
  const CompiledShader c = compileComputeShader(file, options_);
  EXPECT_EQ(spirvMemoryProblem(c.spirv), "");
  EXPECT_EQ(spirvMemoryProblem(c.spirv, {{3u, 1000u}}), "");
  EXPECT_HAS(spirvMemoryProblem(c.spirv, {{3u, 100000u}}), "1600000 bytes");
}

TEST_F(ShaderBoundsTest, EverythingOutsideTaaUserHIsRefusedAtLoad) {
  struct Hostile {
    const char* name;
    std::string decl, value, expected;
  };
  const Hostile cases[] = {
      {"sampler20", "layout(set = 0, binding = 20) uniform sampler2D extra;",
       "texelFetch(extra, p, 0).rgb", "combined image sampler at set 0 binding 20, a binding "
                                      "taa_user.h does not declare"},
      {"ssbo", "layout(set = 0, binding = 21) buffer B { float v[]; } b;",
       "taa_color_at(p) + b.v[0]", "storage buffer at set 0 binding 21"},
      {"written_ssbo", "layout(set = 0, binding = 21) buffer B { float v[]; } b;",
       "vec3(b.v[0] = 1.0)", "storage buffer at set 0 binding 21"},
      {"push", "layout(push_constant) uniform P { vec4 k; } pc;", "taa_color_at(p) + pc.k.rgb",
       "push-constant block (16 bytes)"},
      {"set1", "layout(set = 1, binding = 0) uniform sampler2D other;",
       "texelFetch(other, p, 0).rgb", "set 1 binding 0; taa_user.h uses set 0 only"},
      {"array", "layout(set = 0, binding = 20) uniform sampler2D many[4];",
       "texelFetch(many[1], p, 0).rgb", "binding 20"},
      {"bigubo", "layout(set = 0, binding = 20) uniform U { vec4 v[1000]; } u;",
       "taa_color_at(p) + u.v[p.x].rgb", "uniform buffer at set 0 binding 20"},
  };
  for (const auto& h : cases) {
    SCOPED_TRACE(h.name);
    EXPECT_HAS(refusal(resolve(std::string(h.name) + ".comp", h.decl, h.value)), h.expected);
  }
}

// A resource on a binding the header already uses: the message names both, so that a port's
// texture left without a binding (the compiler's pick) reads as what it is.
TEST_F(ShaderBoundsTest, TwoResourcesOnOneBindingAreNamed) {
  const std::string msg = refusal(resolve(
      "twice.comp", "layout(set = 0, binding = 1) uniform sampler2D _MainTex;",
      "texelFetch(_MainTex, p, 0).rgb + taa_color_at(p)"));
  EXPECT_HAS(msg, "set 0 binding 1 is declared twice, by ");
  EXPECT_HAS(msg, "_MainTex");
  EXPECT_HAS(msg, "taa_color");
}

// Without the header: the declarations clash with what the harness binds.
TEST_F(ShaderBoundsTest, TypeClashesWithTheHeadersBindingsAreRefused) {
  const std::string top = "#version 450\nlayout(local_size_x = 8, local_size_y = 8) in;\n";
  const std::string out = "layout(set = 0, binding = 10, rgba16f) uniform writeonly image2D o;\n";
  const std::string store = "void main() { ivec2 p = ivec2(gl_GlobalInvocationID.xy); ";
  EXPECT_HAS(refusal(write("uint.comp", top + out +
                                            "layout(set = 0, binding = 1) uniform usampler2D c;\n" +
                                            store + "imageStore(o, p, vec4(texelFetch(c, p, 0))); }\n")),
             "taa_color (binding 1) with uint samples");
  EXPECT_HAS(refusal(write("ids.comp", top + out +
                                           "layout(set = 0, binding = 4) uniform sampler2D i;\n" +
                                           store + "imageStore(o, p, texelFetch(i, p, 0)); }\n")),
             "taa_ids (binding 4) with float samples");
  EXPECT_HAS(refusal(write("fmt.comp",
                           top + "layout(set = 0, binding = 10, rgba32f) uniform writeonly image2D o;\n" +
                               store + "imageStore(o, p, vec4(1)); }\n")),
             "another format than rgba16f");
  EXPECT_HAS(refusal(write("img3d.comp", top + out +
                                             "layout(set = 0, binding = 1) uniform sampler3D c;\n" +
                                             store + "imageStore(o, p, texelFetch(c, ivec3(p, 0), 0)); }\n")),
             "single-sampled, non-arrayed 2D");
  EXPECT_HAS(refusal(write("storage.comp",
                           top + out + "layout(set = 0, binding = 1, rgba16f) uniform image2D c;\n" +
                               store + "imageStore(o, p, imageLoad(c, p)); }\n")),
             "storage image at set 0 binding 1, where taa_user.h declares taa_color");
  EXPECT_HAS(refusal(write("ubo.comp",
                           top + out + "layout(set = 0, binding = 0) uniform F { mat4 m[8]; } f;\n" +
                               store + "imageStore(o, p, f.m[7][0]); }\n")),
             "512-byte uniform block at set 0 binding 0");
  // A resolve picks its own flat workgroup (X x Y x 1): a deep one would write pixels twice.
  EXPECT_HAS(refusal(write("wg.comp",
                           "#version 450\nlayout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;\n" +
                               out + store + "imageStore(o, p, vec4(1)); }\n")),
             "workgroup of 4x4x4");
}

TEST_F(ShaderBoundsTest, ConstantIdsAboveTheHeadersRangeAreRefused) {
  EXPECT_HAS(refusal(resolve("id100.comp", "layout(constant_id = 100) const float k = 1.0;",
                             "taa_color_at(p) * k")),
             "constant_id 100; taa_user.h allows 0 to 99");
  accepted(resolve("id99.comp", "layout(constant_id = 99) const float k = 1.0;",
                   "taa_color_at(p) * k"));
}

// Spins until this process has used `d` more of CPU.
void spinCpu(std::chrono::milliseconds d) {
  const auto used = [] {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return std::chrono::seconds(t.tv_sec) + std::chrono::nanoseconds(t.tv_nsec);
  };
  const auto end = used() + d;
  while (used() < end) {
  }
}

TEST(CompileSandbox, ReportsHowTheChildEnded) {
  SandboxLimits l;
  l.cpuSeconds = 1;
  l.wallSeconds = 20;
  EXPECT_EQ(runSandboxed([] { return std::string("words"); }, l).output, "words");
  EXPECT_EQ(runSandboxed([]() -> std::string { ::raise(SIGSEGV); return {}; }, l).end,
            SandboxEnd::Crashed);
  EXPECT_EQ(runSandboxed([]() -> std::string { throw std::bad_alloc(); }, l).end,
            SandboxEnd::OverMemory);
  const SandboxOutcome spin = runSandboxed(
      [] {
        volatile unsigned long n = 0;
        for (;;) n = n + 1;
        return std::string();
      },
      l);
  EXPECT_EQ(spin.end, SandboxEnd::OverTime);
  EXPECT_HAS(describeSandboxEnd(spin, l), "more than 1 s of CPU");
  // A phase with its own budget ends with the reply prepared for it.
  const SandboxOutcome phase = runSandboxed(
      [] {
        sandboxCpuBudget(std::chrono::milliseconds(100), "phase over");
        volatile unsigned long n = 0;
        for (;;) n = n + 1;
        return std::string();
      },
      SandboxLimits{});
  EXPECT_EQ(phase.end, SandboxEnd::Done);
  EXPECT_EQ(phase.output, "phase over");
  // An ended phase's budget no longer counts: the work runs on past it.
  const SandboxOutcome after = runSandboxed(
      [] {
        sandboxCpuBudget(std::chrono::milliseconds(50), "phase over");
        sandboxCpuBudget({}, "");
        spinCpu(std::chrono::milliseconds(200));
        return std::string("whole");
      },
      SandboxLimits{});
  EXPECT_EQ(after.end, SandboxEnd::Done);
  EXPECT_EQ(after.output, "whole");
}

// What the parent makes before the fork (glslang's built-in tables), the child inherits; what
// the child makes, the parent never sees.
TEST(CompileSandbox, InParentRunsFirstAndTheChildInheritsIt) {
  static int made = 0;
  made = 0;
  const SandboxOutcome o = runSandboxed(
      [] {
        const std::string seen = std::to_string(made);
        made = 2;
        return seen;
      },
      SandboxLimits{}, [] { made = 1; });
  EXPECT_EQ(o.end, SandboxEnd::Done);
  EXPECT_EQ(o.output, "1");
  EXPECT_EQ(made, 1);
}

}  // namespace
}  // namespace taa::user

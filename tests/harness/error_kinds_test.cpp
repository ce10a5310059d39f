// Every error type is of one of core/errors.h's two kinds, which alone decide the exit code:
// the dispatcher catches those two. A new type that derives from std::runtime_error directly
// would reach the dispatcher's last resort (exit 3, "error:") whatever it means. The list of
// types is made from the sources (error_types.py, at build time), so a new one cannot be left
// out of it: each is compiled against the two kinds here.
#include <gtest/gtest.h>

#include <string_view>
#include <type_traits>

#include "error_types.inc"

namespace taa::error_kinds_test {

template <class E>
constexpr bool isInput = std::is_base_of_v<InputError, E> && !std::is_base_of_v<EnvironmentError, E>;
template <class E>
constexpr bool isEnvironment =
    std::is_base_of_v<EnvironmentError, E> && !std::is_base_of_v<InputError, E>;
// `--help` is no error: the dispatcher prints the usage and exits 0.
template <class E>
constexpr bool isNoError = std::is_same_v<E, cli::HelpRequested>;

#define TAA_CHECK_KIND(T, FILE)                                                              \
  static_assert(isInput<T> || isEnvironment<T> || isNoError<T>,                             \
                FILE ": " #T " is of neither kind: derive it from InputError (the input is " \
                "wrong, exit 2) or EnvironmentError (this machine, exit 3)");
TAA_ERROR_TYPES(TAA_CHECK_KIND)

#define TAA_COUNT_TYPE(T, FILE) +1
constexpr int kErrorTypes = 0 TAA_ERROR_TYPES(TAA_COUNT_TYPE);

// The list is the sources' own: a scan that found nothing would check nothing.
TEST(ErrorKinds, TheListHoldsEveryDeclaredType) {
  EXPECT_GE(kErrorTypes, 24);
  static_assert(isInput<run::MergeError> && isInput<run::ResultsFormatError>);
}

TEST(ErrorKinds, EachTypeReportsInItsKindsWords) {
  EXPECT_EQ(scene::SceneError("a.gltf: no mesh").report("run"), "error: a.gltf: no mesh");
  EXPECT_EQ(cases::CaseError({"a.json: x: bad", "a.json: y: worse"}).report("run"),
            "error: a.json: x: bad\nerror: a.json: y: worse");
  EXPECT_EQ(cli::UsageError("no case given").report("bless"), "taa-harness bless: no case given");
  EXPECT_EQ(OutputError("out/x.png", "disk full").report("run"),
            "environment: cannot write out/x.png: disk full");
  EXPECT_EQ(DeviceError("vkQueueSubmit failed").report("run"), "vulkan: vkQueueSubmit failed");
  // A failed image write is the disk's, a failed read the file's.
  EXPECT_EQ(ImageWriteError("o.exr", "no space").report("render"), "environment: o.exr: no space");
  EXPECT_EQ(ImageIoError("g.exr", "truncated").report("run"), "error: g.exr: truncated");
}

}  // namespace taa::error_kinds_test

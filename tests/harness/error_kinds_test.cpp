// Every error type is of one of core/errors.h's two kinds, which alone decide the exit code:
// the dispatcher catches those two. A new type that derives from std::runtime_error directly
// would reach the dispatcher's last resort (exit 3, "error:") whatever it means.
#include <gtest/gtest.h>

#include <type_traits>

#include "api/device_error.h"
#include "case/case_error.h"
#include "cli/options.h"
#include "compare/compare_files.h"
#include "core/errors.h"
#include "core/exr_codec.h"
#include "core/image_io.h"
#include "core/input_file.h"
#include "core/output_file.h"
#include "core/png_codec.h"
#include "golden/manifest.h"
#include "scene/scene_error.h"
#include "script/track.h"
#include "user/glsl_compiler.h"
#include "vk/check.h"
#include "vk/spirv_reflect.h"

namespace taa {
namespace {

template <class E>
constexpr bool isInput = std::is_base_of_v<InputError, E> && !std::is_base_of_v<EnvironmentError, E>;
template <class E>
constexpr bool isEnvironment =
    std::is_base_of_v<EnvironmentError, E> && !std::is_base_of_v<InputError, E>;

static_assert(isInput<cases::CaseError> && isInput<cli::UsageError> &&
              isInput<compare::CompareInputError> && isInput<golden::GoldenError>);
static_assert(isInput<scene::SceneError> && isInput<script::TrackError> &&
              isInput<user::ShaderCompileError> && isInput<vk::ShaderInterfaceError> &&
              isInput<UnsupportedSettingError>);
static_assert(isInput<ImageIoError> && isInput<InputFileError> && isInput<png::PngError> &&
              isInput<exr::ExrError>);
static_assert(isEnvironment<ImageWriteError> && isEnvironment<OutputError> &&
              isEnvironment<DeviceError> && isEnvironment<vk::VulkanError>);

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

}  // namespace
}  // namespace taa

// Shared GPU plumbing for tests: one lavapipe context per test process (with a
// hermetic shader cache), and helpers to move float images to and from the device.
#pragma once

#include <string>

#include "api/device.h"
#include "api/frame_record.h"
#include "api/renderer.h"
#include "core/image.h"
#include "spec/case_spec.h"
#include "vk/context.h"
#include "vk/resources.h"

namespace taa::test {

// The device every test of the process shares; gpu() is its Vulkan context.
Device& device();
vk::Context& gpu();

// A device image of `format` (RGBA16F, RGBA32F, RG16F, R32F) holding `image`,
// ready for sampling in compute shaders.
vk::Image uploadFloatImage(const Image& image, VkFormat format, const char* name = "test_input");

// The whole image read back as floats.
Image downloadImage(vk::Image& image);

// Parses a case from JSON text (as if it were cases/NAME.json) with every default filled in.
spec::CaseSpec caseFromJson(const std::string& json, const std::string& name = "test");

// Renders a case and returns every frame's record; images for `framesWithImages`
// (empty: the case's output.frames). `options` adds the reference and captured buffers
// (current colour, ids, velocity) to those frames.
std::vector<FrameRecord> renderCase(const spec::CaseSpec& spec, const std::vector<int>& framesWithImages = {},
                                    const RenderOptions& options = {});

// The same with render options (reference, captures).
std::vector<FrameRecord> renderCaseWith(const spec::CaseSpec& spec, const RenderOptions& options,
                                        const std::vector<int>& framesWithImages = {});

// One of the case's output.aux buffers of a record by name ("depth"); throws when absent.
const Image& auxImage(const FrameRecord& record, const std::string& name);
// A capture of a record (api/captures.h); throws when it was not read back.
const Image& capturedImage(const FrameRecord& record, Capture capture);

}  // namespace taa::test

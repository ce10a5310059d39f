// The loaders' errors the harness catches by name (a track it turns into case problems, a
// shader that does not compile into a validation message), without the loaders' headers. Both
// are InputErrors (exit 2). A scene's SceneError reaches the harness only as an InputError, so
// it stays in scene/scene_error.h.
#pragma once

#include "core/errors.h"

namespace taa::script {

// A track that cannot be replayed. The message names the file and the line, frame
// or key, and the fix.
class TrackError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace taa::script

namespace taa::user {

// The shader does not compile, names a file it may not read, or breaks taa_user.h's contract
// (user_interface.h): bad input. what() is glslang's message with the user's file and line
// first ("my.comp:12: 'x' : undeclared identifier"), or the file and the reason, and the fix.
class ShaderCompileError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace taa::user

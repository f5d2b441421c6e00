// Safe saving of the live view: the scene file's own text with only the
// changed values replaced in place (or inserted into their object), so a
// course file keeps its layout, key order, one-line spheres and number
// formatting; numbers are written in the shortest form that reads back to
// the same value (a panel slider's float 1.1 is "1.1", not
// "1.100000023841858"). An untouched scene saves byte for byte.
#pragma once

#include "core/scene.h"

#include <string>

namespace rl {

// Shortest decimal text that reads back as `v`; a value that is exactly a
// float (as the panel's sliders make them) in the float's shortest form.
std::string shortestNumber(double v);

// `text` (the file `original` was read from) with every value in which
// `edited` differs from `original` written over. The camera is compared
// like every other value: pass edited.camera = original.camera to keep it.
// Throws rl::Error when the spheres or lights were added or removed (the
// caller then writes the whole scene).
std::string patchSceneText(const std::string& text, const Scene& original, const Scene& edited);

// True for files under the repository's scenes/ (bundled and course
// scenes): the view asks before writing over them.
bool isBundledScene(const std::string& path);

// Where "save" writes by default: SCENE-edited.json beside the scene, or in
// the working directory for a bundled scene or the embedded one
// (scene-edited.json); "-2", "-3", ... when the name is taken.
std::string defaultSavePath(const std::string& scenePath);

}  // namespace rl

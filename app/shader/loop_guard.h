// Bounded student loops. A loop that never ends hangs a GPU (the driver
// resets after seconds), freezes every WebGL context of a browser page, and
// on llvmpipe is cut after 65535 iterations, so the same file would earn a
// TIMEOUT, a frozen page or a plausible picture with marks. So the host
// rewrites every loop of an exercise file (never a framework file) before
// the driver sees it:
//     for (init; cond; step)   ->  for (init; rl_loop((cond), ID); step)
//     while (cond)             ->  while (rl_loop((cond), ID))
//     do { } while (cond);     ->  do { } while (rl_loop((cond), ID));
// rl_loop (shaders/loop_guard.glsl) counts the iterations of each run of a
// guarded loop, and of all of them in one invocation (one pixel, one probe
// case); past kLoopLimit in one run, or kLoopTotalLimit in all, it ends every
// loop and records the loop that went over, which main.frag
// and probe.frag write into their output's alpha as -ID. The host reads it
// back and reports TIMEOUT naming that loop's file and line, the same on every
// machine. No newline is added, so every line keeps its number.
//
// Refused (an error naming the file and line, before compiling): a loop
// keyword inside a #define (the loop would escape the guard), a condition
// that declares a variable (`while (bool b = f())`), and an array over
// kMaxArrayElements elements (no GPU gives one pixel that much memory: a
// verdict of TIMEOUT or CRASH would depend on the machine).
#pragma once

#include "gl/gl_api.h"
#include "shader/program.h"
#include "shader/source_assembler.h"

#include <string>
#include <vector>

namespace rl {

// Iterations of an exercise file's loops allowed in one invocation. A
// finished exercise needs a few hundred at most (09's bounce loop runs
// maxBounces() + 1 <= 9 times per sample, 4 samples per pixel in the check
// scenes); 16384 leaves a factor of 400 for loops students add (a pow by
// repeated multiplication per light and bounce) and stays below llvmpipe's
// own cap of 65535 iterations per invocation, with room for the framework's
// loops (spheres x lights x bounces x samples: about 1000), so the guard, not
// llvmpipe, ends a runaway loop.
constexpr int kLoopLimit = 16384;
// That limit is per run of one loop (from its first test to the false test
// that ends it), so a bounded loop that a function runs on every call (D_GGX
// for every light, bounce and sample of a pixel) is never cut for the calls
// it adds up to. All guarded loops of one invocation together may run at
// most kLoopTotalLimit iterations: llvmpipe ends every loop of an invocation
// after 65535 in all, and the framework's own loops take about 1000 of them,
// so past 60000 the guard, not llvmpipe, decides (an endless outer loop
// around a bounded inner one meets this bound).
constexpr int kLoopTotalLimit = 60000;
// A loop that met the total is recorded as kLoopTotalFlag + its ID.
constexpr int kLoopTotalFlag = 65536;
// The largest literal bound of a for loop that needs no guard (a counter
// from a literal up to it, or to maxBounces(), untouched in the body): 64
// iterations a run, three such loops nested 262144, the most any of them
// can add to an invocation.
constexpr long kUnguardedBound = 64;
// Elements of one array in an exercise file: an exercise needs a handful.
constexpr long kMaxArrayElements = 4096;

struct GuardedSource {
    std::string text;                   // same lines as the input, loops guarded
    std::vector<int> loopLines;         // 1-based line of each loop, in ID order (ID = firstId + index)
};

// Rewrites the loops of one exercise file. `shown` names the file in errors;
// loop IDs start at `firstId` (>= 1). Throws rl::Error "shown:line: error: ..."
// for what cannot be bounded. Linear in the text's length; never recurses.
GuardedSource guardLoops(const std::string& text, const std::string& shown, int firstId);

// The first guarded loop that went over the limit in a result: `alpha` is
// the output's alpha channel (-ID where a loop tripped). 0 when none did.
int trippedLoop(const std::vector<float>& alpha);

// Reads the alpha channel of colour attachment `attachment` of `framebuffer`
// (width x height, RGBA32F) and returns trippedLoop of it.
int trippedLoopInFramebuffer(GLuint framebuffer, int attachment, int width, int height);

// A driver message about rl_loop is about the student's loop condition (GLSL
// converts no number to bool: `while (1)`): says so, without naming rl_loop.
void explainLoopGuard(ShaderDiagnostic& diagnostic);

// "a loop in 05-ggx.glsl:12 ran more than 16384 iterations without its
// condition becoming false, in one pixel..." (or, for kLoopTotalFlag + ID,
// "the loops ran more than 60000 iterations in all ...; the last one tested
// was 05-ggx.glsl:12") for a tripped ID of an assembly
// (AssembledSource::loops), with the file's name only.
std::string loopTimeoutMessage(const std::vector<SourceLocation>& loops, int id, const std::string& where);

}  // namespace rl

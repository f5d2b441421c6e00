// loop_guard.glsl: the iteration guard the host writes into every loop of an
// exercise file (app/shader/loop_guard.h): `while (cond)` is compiled as
// `while (rl_loop((cond), ID))`. A loop that never ends would hang a GPU and
// freeze a browser; llvmpipe would cut it after 65535 iterations and draw a
// plausible picture. With the guard it ends the same way everywhere: past
// RL_LOOP_LIMIT iterations of all guarded loops in one invocation, every
// guarded loop stops and the first one over is recorded; main.frag and
// probe.frag write -ID into their output's alpha and the checker reports
// TIMEOUT with that loop's file and line.

// Iterations of the exercise files' loops allowed per invocation (one pixel,
// one probe case); the reason for the number is at kLoopLimit in
// app/shader/loop_guard.h, and a test checks that both agree.
const int RL_LOOP_LIMIT = 16384;

int rl_loopIterations = 0;  // guarded iterations so far in this invocation
int rl_loopTripped = 0;     // ID of the first loop that went over the limit; 0 while none did

bool rl_loop(bool condition, int loop) {
    if (!condition) return false;
    if (rl_loopIterations >= RL_LOOP_LIMIT) {
        if (rl_loopTripped == 0) rl_loopTripped = loop;
        return false;
    }
    ++rl_loopIterations;
    return true;
}

// The alpha an output carries: `normal`, or -ID of the loop that went over.
float loopGuardAlpha(float normal) { return rl_loopTripped != 0 ? -float(rl_loopTripped) : normal; }

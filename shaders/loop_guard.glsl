// loop_guard.glsl: the iteration guard the host writes into every loop of an
// exercise file (app/shader/loop_guard.h): `while (cond)` is compiled as
// `while (rl_loop((cond), ID))`. A loop that never ends would hang a GPU and
// freeze a browser; llvmpipe would cut it after 65535 iterations and draw a
// plausible picture. With the guard it ends the same way everywhere: past
// RL_LOOP_LIMIT iterations of one run of a loop, or RL_LOOP_TOTAL_LIMIT of
// all guarded loops in one invocation, every guarded loop stops and the one
// that went over is recorded; main.frag and
// probe.frag write -ID into their output's alpha and the checker reports
// TIMEOUT with that loop's file and line.

// Iterations allowed to one run of one guarded loop (from its first test of
// the condition to the test that ends it), and to all guarded loops of one
// invocation (one pixel, one probe case) together; the reasons for the
// numbers are at kLoopLimit and kLoopTotalLimit in app/shader/loop_guard.h,
// and a test checks that both sides agree. A loop that went over the total
// is recorded as RL_LOOP_TOTAL_FLAG + ID, so the host can say which bound it met.
const int RL_LOOP_LIMIT = 16384;
const int RL_LOOP_TOTAL_LIMIT = 60000;
const int RL_LOOP_TOTAL_FLAG = 65536;

int rl_loopCurrent = 0;     // the loop whose run is being counted
int rl_loopIterations = 0;  // iterations of that run so far
int rl_loopTotal = 0;       // guarded iterations so far in this invocation, all loops
int rl_loopTripped = 0;     // what went over first (ID, or RL_LOOP_TOTAL_FLAG + ID); 0 while nothing did

bool rl_loop(bool condition, int loop) {
    if (rl_loopTripped != 0) return false;  // once one loop ran away, every guarded loop ends
    // Another loop's test (the next loop, or an inner or outer one) starts a new count. A run ends
    // when its condition is false; a loop left by break or return keeps its count until
    // another loop is tested, which can only count more, never less.
    if (loop != rl_loopCurrent) {
        rl_loopCurrent = loop;
        rl_loopIterations = 0;
    }
    if (!condition) {
        rl_loopIterations = 0;
        return false;
    }
    if (rl_loopIterations >= RL_LOOP_LIMIT) {
        rl_loopTripped = loop;
        return false;
    }
    if (rl_loopTotal >= RL_LOOP_TOTAL_LIMIT) {
        rl_loopTripped = RL_LOOP_TOTAL_FLAG + loop;
        return false;
    }
    ++rl_loopIterations;
    ++rl_loopTotal;
    return true;
}

// The condition of a loop that needs no guard (a counter up to a small
// bound, shader/loop_guard.h), counted in the invocation's total so that the
// guards of the loops around it see its iterations.
bool rl_counted(bool condition) {
    rl_loopTotal += condition ? 1 : 0;
    return condition;
}

// The alpha an output carries: `normal`, or -ID of the loop that went over.
float loopGuardAlpha(float normal) { return rl_loopTripped != 0 ? -float(rl_loopTripped) : normal; }

#include "bench/frame_clock.h"

#include "gl/gl_api.h"

#include <algorithm>
#include <ctime>

namespace rl::bench {

bool isSoftwareRasteriser(const std::string& description) {
    for (const char* name : {"llvmpipe", "softpipe", "SwiftShader", "lavapipe"})
        if (description.find(name) != std::string::npos) return true;
    return false;
}

double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double timeFrame(GlRenderer& renderer, const PictureProgram& program, const FrameSettings& frame, Clock clock) {
    if (clock == Clock::Gpu) return renderer.drawTimed(program, frame);
    gl::Finish();
    if (clock == Clock::Cpu) {
        const double t0 = processCpuMs();
        renderer.draw(program, frame);
        gl::Finish();
        return processCpuMs() - t0;
    }
    const auto t0 = std::chrono::steady_clock::now();
    renderer.draw(program, frame);
    gl::Finish();
    return msSince(t0);
}

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace rl::bench

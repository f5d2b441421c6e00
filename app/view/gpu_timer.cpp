#include "view/gpu_timer.h"

namespace rl {

GpuTimer::GpuTimer() { gl::GenQueries(kQueries, queries_.data()); }

GpuTimer::~GpuTimer() { gl::DeleteQueries(kQueries, queries_.data()); }

bool GpuTimer::begin(double tag) {
    if (pending_ == kQueries) return false;
    tags_[head_] = tag;
    gl::BeginQuery(GL_TIME_ELAPSED, queries_[head_]);
    running_ = true;
    return true;
}

void GpuTimer::end() {
    if (!running_) return;
    gl::EndQuery(GL_TIME_ELAPSED);
    running_ = false;
    head_ = (head_ + 1) % kQueries;
    ++pending_;
}

std::optional<GpuTimer::Result> GpuTimer::poll() {
    if (pending_ == 0) return std::nullopt;
    const int slot = (head_ - pending_ + kQueries) % kQueries;
    GLuint oldest = queries_[slot];
    GLint available = 0;
    gl::GetQueryObjectiv(oldest, GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) return std::nullopt;
    GLuint64 nanoseconds = 0;
    gl::GetQueryObjectui64v(oldest, GL_QUERY_RESULT, &nanoseconds);
    --pending_;
    return Result{double(nanoseconds) * 1e-6, tags_[slot]};
}

}  // namespace rl

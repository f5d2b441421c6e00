// The probe cases are the same on every compiler: every random draw is
// sequenced (course/*/probes.cpp), so g++ and clang++ build the same
// inputs, in the same order, with the same counts. A hash of all of them is
// pinned here: a change in the order of the draws, a seed, a count or a
// group changes it.
//
// What is hashed: per exercise, per probe, the name, the number of cases and
// each case's group and its 24 inputs rounded to 16 significant bits. The
// rounding is there because float arithmetic itself is not the same
// everywhere: g++ -O2 (its vectoriser) keeps one product of exercise 04's
// "grazing light on a large ground" group in double where clang++ -O2,
// g++ -O0 and the sanitizer build round it to float first, so 6 inputs differ
// by 1 ulp (2^-24). 16 bits are far coarser than that and far finer than
// any change of the draws, which moves every input entirely. Checked: the
// same hash from g++ -O2, g++ -O0, g++ -O2 with ASan+UBSan, and clang++ 14 -O2.
#include "checks/probe_cases.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

using namespace rl;

namespace {

struct Fnv1a {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) {
            h ^= b[i];
            h *= 1099511628211ull;
        }
    }
    void text(const std::string& s) {
        std::uint64_t n = s.size();
        bytes(&n, sizeof n);
        bytes(s.data(), s.size());
    }
    void integer(std::int64_t v) { bytes(&v, sizeof v); }
};

// x rounded to 16 significant bits, as (exponent, mantissa) integers.
void roundedInput(Fnv1a& hash, float x) {
    if (x == 0 || !std::isfinite(x)) {
        hash.integer(x == 0 ? 0 : std::isnan(x) ? 1 : x > 0 ? 2 : 3);
        return;
    }
    int exponent = 0;
    double mantissa = std::frexp(double(x), &exponent);  // [0.5, 1)
    hash.integer(exponent);
    hash.integer(std::llround(std::ldexp(mantissa, 16)));
}

std::string hashOfExercise(int number, Fnv1a& all) {
    Fnv1a one;
    for (Fnv1a* h : {&one, &all})
        for (const ProbeSpec& spec : probesForExercise(number)) {
            h->text(spec.name);
            h->integer(std::int64_t(spec.cases.size()));
            for (const ProbeCase& c : spec.cases) {
                h->text(c.group);
                for (float x : c.in) roundedInput(*h, x);
            }
        }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(one.h));
    return text;
}

}  // namespace

TEST(ProbeCases, AreTheSameOnEveryCompiler) {
    // Printed per exercise, so a failure says which exercise's cases moved.
    const char* pinned[10] = {
        "ba2335859d616288", "647d2e49e98e2b15", "4746a1127a3126d0", "2747ad3f7fed7813", "a51dcf6637b77ff7",
        "73472b6f1005ae4c", "80061ade834b5b8c", "100a3969fd3c8f8e", "a78d4a37c161e3b6", "75e60b6da2e30741",
    };
    Fnv1a all;
    for (int e = 1; e <= 10; ++e) EXPECT_EQ(hashOfExercise(e, all), pinned[e - 1]) << "exercise " << e;
}

TEST(ProbeCases, CountsArePinned) {
    // The counts alone, readable: clang++ and g++ once gave exercise 04 88 and 85 visibility cases.
    const int pinned[10] = {110, 148, 81, 137, 76, 80, 56, 248, 112, 130};
    for (int e = 1; e <= 10; ++e) {
        int total = 0;
        for (const ProbeSpec& spec : probesForExercise(e)) total += int(spec.cases.size());
        EXPECT_EQ(total, pinned[e - 1]) << "exercise " << e;
    }
}

// The hint rules of the checker on numbers made on the CPU (no GPU, no
// shader): a hint names a cause only when the student's numbers support it.
//   - a known mistake is named when the numbers match it on EVERY case, and
//     every known mistake of every probe is recognised from its own numbers;
//   - a mistake matched only where it differs from the right answer is not;
//   - one constant factor on every case is named with its number (pi
//     written as 3.14);
//   - a group hint ("fails mostly on X") only when X holds at least half of
//     the failures and fails far more often than the other inputs;
//   - failures spread over every kind of input are said to be so;
//   - every mistake a handout lists is known to the checker by name and has
//     a mutant in course/*/mutants/.
#include "checks/checker.h"
#include "checks/probe_cases.h"
#include "course/exercise_registry.h"
#include "core/paths.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <regex>
#include <sstream>

using namespace rl;

namespace {

using Raw = std::vector<std::array<float, 4>>;

Raw resultsOf(const ProbeSpec& spec, const std::function<ProbeValue(const ProbeCase&)>& student) {
    Raw raw;
    for (const ProbeCase& c : spec.cases) {
        ProbeValue v = student(c);
        raw.push_back({float(v[0]), float(v[1]), float(v[2]), 0.0f});
    }
    return raw;
}

ProbeSpec probeNamed(int exercise, const std::string& name) {
    for (ProbeSpec& spec : probesForExercise(exercise))
        if (spec.name == name) return spec;
    ADD_FAILURE() << "no probe " << name << " in exercise " << exercise;
    return probesForExercise(exercise).front();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

ProbeValue scaled(ProbeValue v, double k) { return {k * v[0], k * v[1], k * v[2]}; }

}  // namespace

TEST(Hints, RightAnswersPassWithoutAHint) {
    for (const ExerciseInfo& e : allExercises())  // the optional 11 too
        for (const ProbeSpec& spec : probesForExercise(e.number)) {
            ProbeOutcome o = evaluateProbe(spec, resultsOf(spec, spec.expected));
            EXPECT_EQ(o.summary.passed, o.summary.total) << spec.name << ": " << o.firstFailure;
            EXPECT_TRUE(o.hint.empty()) << spec.name << ": " << o.hint;
        }
}

TEST(Hints, EveryKnownMistakeIsRecognisedFromItsOwnNumbers) {
    int named = 0;
    for (const ExerciseInfo& e : allExercises())  // the optional 11 too
        for (const ProbeSpec& spec : probesForExercise(e.number))
            for (const KnownMistake& m : spec.mistakes) {
                ProbeOutcome o = evaluateProbe(spec, resultsOf(spec, m.compute));
                ASSERT_LT(o.summary.passed, o.summary.total) << spec.name << ": '" << m.symptom << "' changes nothing";
                // An earlier mistake may explain the same numbers (a fixed
                // offset of 1e-5 and of 1e-4 agree where both are tiny);
                // then that one is named, and it must match on every case too.
                EXPECT_TRUE(contains(o.hint, "looks like: ")) << spec.name << ": '" << m.symptom << "' got " << o.hint;
                named += contains(o.hint, "looks like: " + m.symptom + ". " + m.hint);
            }
    EXPECT_GE(named, 40);
}

TEST(Hints, AMistakeMatchedOnlyWhereItDiffersIsNotNamed) {
    // The aspect ratio on y agrees with the right answer on square images.
    // Numbers that match it on non-square images but are wrong on square
    // ones are not that mistake (before, 80% of the differing cases sufficed).
    ProbeSpec rays = probeNamed(1, "cameraRayDirection");
    const KnownMistake* aspect = nullptr;
    for (const KnownMistake& m : rays.mistakes)
        if (contains(m.symptom, "aspect ratio scales y")) aspect = &m;
    ASSERT_NE(aspect, nullptr);
    ProbeOutcome o = evaluateProbe(rays, resultsOf(rays, [&](const ProbeCase& c) {
        return c.group == "square image" ? scaled(rays.expected(c), 0.9) : aspect->compute(c);
    }));
    EXPECT_FALSE(contains(o.hint, "looks like")) << o.hint;
    EXPECT_FALSE(contains(o.hint, "aspect ratio")) << o.hint;
    EXPECT_TRUE(contains(o.hint, "of every kind: compare your formula")) << o.hint;
}

TEST(Hints, FailuresSpreadOverEveryKindOfInputNameNoGroup) {
    // 01 with two mistakes at once (+0.5 again and no normalize): no known
    // mistake, no common factor, every input kind wrong: not "aspect ratio".
    ProbeSpec rays = probeNamed(1, "cameraRayDirection");
    ProbeOutcome o = evaluateProbe(rays, resultsOf(rays, [](const ProbeCase& c) {
        auto in = [&](int k) { return double(c.in[std::size_t(k)]); };
        double t = std::tan(in(4) / 2), aspect = in(2) / in(3);
        double x = (2 * (in(0) + 0.5) / in(2) - 1) * t * aspect, y = (2 * (in(1) + 0.5) / in(3) - 1) * t;
        ProbeValue d;
        for (int i = 0; i < 3; ++i) d[std::size_t(i)] = x * in(8 + i) + y * in(12 + i) + in(16 + i);
        return d;
    }));
    EXPECT_FALSE(contains(o.hint, "aspect ratio")) << o.hint;
    EXPECT_TRUE(contains(o.hint, "of every kind: compare your formula")) << o.hint;
}

TEST(Hints, AGroupIsNamedOnlyWhenItsFailuresStandOut) {
    ProbeSpec p = probeNamed(2, "intersectSphere");
    auto wrongWhere = [&](const std::function<bool(const ProbeCase&, int)>& wrong) {
        int k = 0;
        return evaluateProbe(p, resultsOf(p, [&](const ProbeCase& c) {
            ProbeValue v = p.expected(c);
            if (wrong(c, k++)) v[0] += 1.0;
            return v;
        }));
    };
    // Only the far spheres fail: named.
    ProbeOutcome far = wrongWhere([](const ProbeCase& c, int) { return c.group == "far sphere (distance 1e3 to 1e4)"; });
    EXPECT_TRUE(contains(far.hint, "fails mostly on far sphere")) << far.hint;
    // Every case at the centre fails, but they are 6 of 26 failures: a
    // minority, so not "mostly" there.
    int inFront = 0;
    ProbeOutcome minority = wrongWhere([&](const ProbeCase& c, int) {
        return c.group == "origin at the centre" || (c.group == "sphere in front" && inFront++ < 20);
    });
    EXPECT_FALSE(contains(minority.hint, "fails mostly")) << minority.hint;
    EXPECT_TRUE(contains(minority.hint, "origin at the centre (6 of 6)")) << minority.hint;
    EXPECT_TRUE(contains(minority.hint, "sphere in front (20 of 40)")) << minority.hint;
    // Half of the far spheres and a third of everything else: no group stands out.
    ProbeOutcome even = wrongWhere([](const ProbeCase& c, int k) {
        return c.group == "far sphere (distance 1e3 to 1e4)" ? k % 2 == 0 : k % 3 == 0;
    });
    EXPECT_FALSE(contains(even.hint, "fails mostly")) << even.hint;
}

TEST(Hints, OneConstantFactorOnEveryCaseIsNamedWithItsNumber) {
    const double pi = 3.14159265358979323846;
    ProbeSpec d = probeNamed(5, "D_GGX");
    ProbeOutcome o = evaluateProbe(d, resultsOf(d, [&](const ProbeCase& c) { return scaled(d.expected(c), pi / 3.14); }));
    EXPECT_LT(o.summary.passed, o.summary.total);
    EXPECT_TRUE(contains(o.hint, "every value is 1.000507 times the right one: pi written as 3.14:")) << o.hint;
    ProbeSpec fd = probeNamed(3, "Fd_Lambert");
    ProbeOutcome l = evaluateProbe(fd, resultsOf(fd, [&](const ProbeCase& c) { return scaled(fd.expected(c), pi / 3.1416); }));
    EXPECT_LT(l.summary.passed, l.summary.total) << "3.1416 for pi must fail Fd_Lambert";
    EXPECT_TRUE(contains(l.hint, "pi written as 3.1416")) << l.hint;
    // Any other factor: the number, and no invented cause.
    ProbeOutcome k = evaluateProbe(fd, resultsOf(fd, [&](const ProbeCase& c) { return scaled(fd.expected(c), 1.25); }));
    EXPECT_TRUE(contains(k.hint, "every value is 1.25 times the right one: a constant factor is off")) << k.hint;
}

TEST(Hints, EveryMistakeAHandoutListsIsKnownByNameAndHasAMutant) {
    namespace fs = std::filesystem;
    // The mutants' "caught by" texts, per exercise.
    std::map<std::string, std::vector<std::string>> caughtBy;
    const std::regex header(R"re(// mutant of: (\d\d)-[\s\S]*?// caught by: .* contains "(.*)")re");
    for (const std::string& mutant : test::unitFileNames("mutants")) {
        std::string text = test::readText(test::unitFilePath("mutants", mutant));
        std::smatch m;
        if (std::regex_search(text, m, header)) caughtBy[m[1]].push_back(m[2]);
    }
    int rows = 0;
    for (const ExerciseInfo& e : allExercises()) {
        const std::string name = e.handout();
        std::vector<ProbeSpec> specs = unitProbes(e.id);
        // The first table of "Mistakes the checker recognises": | what you see | the checker's hint |
        std::istringstream lines(test::readText(sourceRoot() / e.handout()));
        std::string line;
        bool inSection = false, inTable = false;
        while (std::getline(lines, line)) {
            if (line.rfind("## ", 0) == 0) inSection = line == "## Mistakes the checker recognises";
            if (!inSection) continue;
            if (line == "| what you see | the checker's hint |") {
                inTable = true;
                continue;
            }
            if (inTable && line.rfind("|---", 0) == 0) continue;
            if (inTable && line.rfind("| ", 0) != 0) break;  // the end of the first table
            if (!inTable) continue;
            std::string row = std::regex_replace(line, std::regex(R"(\\\|)"), "!");  // \| inside a cell
            std::smatch cells;
            ASSERT_TRUE(std::regex_match(row, cells, std::regex(R"(\| (.*) \| (.*) \|)"))) << name << ": " << line;
            std::string symptom = std::regex_replace(cells[1].str(), std::regex("!"), "|");
            std::string hint = std::regex_replace(cells[2].str(), std::regex("!"), "|");
            ++rows;
            // Known by name: a KnownMistake with this symptom or this hint,
            // or the constant-factor rule (pi written as 3.14).
            bool known = symptom.rfind("every value is ", 0) == 0 && contains(hint, "pi written as 3.14");
            for (const ProbeSpec& spec : specs)
                for (const KnownMistake& m : spec.mistakes) known = known || m.symptom == symptom || m.hint == hint;
            EXPECT_TRUE(known) << name << ": the checker does not know \"" << symptom << "\"";
            bool mutant = false;
            for (const std::string& text : caughtBy[e.id.substr(0, 2)])
                mutant = mutant || contains(symptom + " " + hint, text);
            EXPECT_TRUE(mutant) << name << ": no mutant in course/*/mutants/ is caught as \"" << symptom << "\"";
        }
    }
    EXPECT_GE(rows, 40);
}

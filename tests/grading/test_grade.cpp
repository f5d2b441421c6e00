// `raylab grade` end to end, through the binary: a class built at test time
// (grading/class_fixture.h) graded with llvmpipe, every student's marks and
// reason, resume and --force, determinism, shards and merge, the HTML report
// in headless Chromium, and Gradescope's container layout.
#include "grading/class_fixture.h"
#include "grading/grade_run.h"
#include "support/test_support.h"

#include "core/image.h"
#include "core/paths.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;
using namespace rl::test;

namespace {

// Seconds per exercise in these tests: short, so that the endless loop costs
// little, yet several times what a check takes with a cold shader cache on
// a loaded 2-core machine (about 1 s), so that no honest check times out.
constexpr int kTimeout = 8;

std::string gradeArgs(const fs::path& submissions, const fs::path& out, const std::string& extra = "") {
    return "grade " + submissions.string() + " -o " + out.string() + " --jobs 2 --timeout " +
           std::to_string(kTimeout) + " " + extra;
}

json readJson(const fs::path& path) { return json::parse(readText(path)); }

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

// One exercise of a student's record (OUT/<id>/grade.json) with its points
// from results.json.
struct Graded {
    std::string status;  // PASS, FAIL, ..., REFUSED
    std::string message;
    std::string feedback;  // results.json's output for the exercise
    double points = 0, maxPoints = 0;
    double seconds = 0;
    json record;
};

struct Student {
    std::map<std::string, Graded> exercises;
    double score = 0;
    double seconds = 0;
    std::vector<std::string> notes;
};

Student load(const fs::path& out, const std::string& id) {
    Student s;
    json record = readJson(out / id / "grade.json");
    json results = readJson(out / id / "results.json");
    s.score = results.at("score").get<double>();
    s.seconds = record.at("seconds").get<double>();
    s.notes = record.at("notes").get<std::vector<std::string>>();
    for (std::size_t k = 0; k < record.at("exercises").size(); ++k) {
        const json& r = record["exercises"][k];
        const json& t = results["tests"][k];
        Graded g;
        g.status = r.value("refused", false) ? "REFUSED" : r.at("status").get<std::string>();
        g.message = r.at("message").get<std::string>();
        g.seconds = r.at("seconds").get<double>();
        g.feedback = t.at("output").get<std::string>();
        g.points = t.at("score").get<double>();
        g.maxPoints = t.at("max_score").get<double>();
        g.record = r;
        s.exercises[r.at("exercise").get<std::string>()] = g;
    }
    return s;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

const std::vector<std::string> kAll = {"01-camera", "02-intersect", "03-lambert",       "04-shadows",     "05-ggx",
                                       "06-geometry", "07-fresnel", "08-cook-torrance", "09-reflections", "10-display"};

// The student has full marks on every exercise but `except`.
void expectOthersFull(const Student& s, const std::string& id, const std::set<std::string>& except) {
    for (const auto& [exercise, g] : s.exercises) {
        if (except.count(exercise)) continue;
        EXPECT_EQ(g.status, "PASS") << id << " " << exercise << ": " << g.message;
        EXPECT_DOUBLE_EQ(g.points, g.maxPoints) << id << " " << exercise;
    }
}

const std::vector<std::string> kMutants = {"03-lambert--missing-pi", "07-fresnel--one-plus-f0",
                                           "09-reflections--reflect-swapped", "10-display--pow-gamma"};

// Student id -> the line put at the top of toneMap in 10-display.glsl.
std::map<std::string, std::string> runawayLoops() {
    return {{"runaway-bound", "    for (int i = 0; i < 1000000000 + maxBounces(); ++i) { c = c * 0.5 + 0.5 * c; }\n"},
            {"runaway-break", "    float spin = 1.0; while (true) { spin += 1.0; if (spin < 0.0) break; }\n"}};
}

// The line of toneMap's first statement in 10-display.glsl.
int toneMapBodyLine() {
    const std::string text = solutionFiles()["10-display.glsl"];
    const auto at = text.find("vec3 toneMap(vec3 c, int op) {\n");
    return 2 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
}

// The whole class: every case of the grading policy.
fs::path buildClass(const fs::path& root) {
    fs::path sub = root / "submissions";
    fs::create_directories(sub);
    writeFolder(sub / "full", solutionFiles());
    writeFolder(sub / "zero", stubFiles());
    for (const std::string& m : kMutants) {
        std::string exercise = m.substr(0, m.find("--"));
        writeFolder(sub / ("mutant-" + m), solutionFiles({{exercise + ".glsl", mutantText(m)}}));
    }
    writeFolder(sub / "compile-error", solutionFiles({{"05-ggx.glsl", compileErrorGgx()}}));
    writeFolder(sub / "endless", solutionFiles({{"10-display.glsl", endlessDisplay()}}));
    // An empty endless loop, which llvmpipe's loop cap alone would end and render: TIMEOUT, as on a GPU.
    std::string whileTrue = solutionFiles()["10-display.glsl"];
    whileTrue.insert(whileTrue.find("vec3 toneMap(vec3 c, int op) {\n") + 31, "    while (true) {}\n");
    writeFolder(sub / "while-true", solutionFiles({{"10-display.glsl", whileTrue}}));
    // Loops that never end but that no reading can prove endless: a bound a
    // billion iterations away read from a uniform, a break never met. The
    // loop guard ends both (app/shader/loop_guard.h): TIMEOUT with the loop's line.
    for (const auto& [id, loop] : runawayLoops()) {
        std::string text = solutionFiles()["10-display.glsl"];
        text.insert(text.find("vec3 toneMap(vec3 c, int op) {\n") + 31, loop);
        writeFolder(sub / id, solutionFiles({{"10-display.glsl", text}}));
    }
    writeFolder(sub / "nan", solutionFiles({{"03-lambert.glsl", nanLambert()}}));
    writeFolder(sub / "include-escape",
                solutionFiles({{"05-ggx.glsl", "#include \"../../full/05-ggx.glsl\"\n"}}));
    auto linked = solutionFiles();
    linked.erase("05-ggx.glsl");
    writeFolder(sub / "symlink", linked);
    fs::create_symlink("../full/05-ggx.glsl", sub / "symlink" / "05-ggx.glsl");
    fs::create_directories(sub / "empty");
    std::string latin1 = solutionFiles()["03-lambert.glsl"];
    // Outside a comment (inside one it is read as Windows-1252: the cp1252 student of
    // GradeRun.EveryNameShapeIsGradedOnceAndNothingDropsSilently).
    latin1.insert(latin1.find('\n') + 1, "float r\xe9sum\xe9 = 1.0;\n");
    writeFolder(sub / "non-utf8", solutionFiles({{"03-lambert.glsl", latin1}}));
    std::string big = solutionFiles()["05-ggx.glsl"] + "// " + std::string(300 * 1024, 'x') + "\n";
    writeFolder(sub / "oversize", solutionFiles({{"05-ggx.glsl", big}}));
    auto partial = solutionFiles();
    for (const char* name : {"04-shadows.glsl", "05-ggx.glsl", "06-geometry.glsl", "07-fresnel.glsl",
                             "08-cook-torrance.glsl", "09-reflections.glsl", "10-display.glsl"})
        partial.erase(name);
    partial["README.md"] = "my notes\n";
    writeFolder(sub / "partial", partial);

    std::vector<ZipEntry> zipped;
    for (const auto& [name, text] : solutionFiles()) zipped.push_back({"exercises/" + name, text});
    writeZip(sub / "zipped.zip", zipped);
    writeText(sub / "corrupt.zip", "PK\x03\x04 this is not a zip archive");
    auto slip = zipped;
    slip.push_back({"../evil.glsl", "// outside\n"});
    writeZip(sub / "zip-slip.zip", slip);
    auto linkZip = zipped;
    linkZip.erase(std::remove_if(linkZip.begin(), linkZip.end(),
                                 [](const ZipEntry& e) { return e.name == "exercises/05-ggx.glsl"; }),
                  linkZip.end());
    linkZip.push_back({"exercises/05-ggx.glsl", "../../full/05-ggx.glsl", true});
    writeZip(sub / "zip-symlink.zip", linkZip);
    auto bomb = zipped;
    bomb.push_back({"exercises/padding.glsl", std::string(8u << 20, ' ')});  // 8 MiB of spaces: ratio ~1000:1
    writeZip(sub / "zip-bomb.zip", bomb);
    // Shapes real uploads take: a repository's zip (a 20 MiB library in build/,
    // .git, a stray stub at the top), and renamed files with a byte-order mark.
    std::vector<ZipEntry> repo;
    for (const auto& [name, text] : solutionFiles()) repo.push_back({"raylab-main/exercises/" + name, text});
    std::string library(20u << 20, '\0');
    std::uint32_t x = 7;
    for (char& c : library) c = char((x = x * 1664525u + 1013904223u) >> 24);  // incompressible, like a real one
    repo.push_back({"raylab-main/build/libraylab_core.a", library});
    repo.push_back({"raylab-main/.git/HEAD", "ref: refs/heads/main\n"});
    repo.push_back({"05-ggx.glsl", stubFiles()["05-ggx.glsl"]});
    writeZip(sub / "messy-repo.zip", repo);
    auto renamed = solutionFiles();
    renamed["05-ggx (1).glsl"] = renamed["05-ggx.glsl"];
    renamed.erase("05-ggx.glsl");
    renamed["07-fresnel.GLSL"] = renamed["07-fresnel.glsl"];
    renamed.erase("07-fresnel.glsl");
    renamed["03-lambert.glsl"] = "\xEF\xBB\xBF" + renamed["03-lambert.glsl"];
    writeFolder(sub / "renamed", renamed);
    // Four folders deep inside a zip inside a zip; a folder named like an
    // exercise file; a macro bomb.
    std::vector<ZipEntry> inner;
    for (const auto& [name, text] : solutionFiles()) inner.push_back({"Desktop/graphics/hw/raylab/exercises/" + name, text});
    writeZip(root / "inner.zip", inner);
    writeZip(sub / "nested-zips.zip", {{"hand-in/inner.zip", readText(root / "inner.zip")}, {"notes.txt", "hi"}});
    auto folderNamed = solutionFiles();
    folderNamed.erase("06-geometry.glsl");
    folderNamed["06-geometry.glsl/notes.glsl"] = "// my notes\n";
    writeFolder(sub / "folder-named", folderNamed);
    std::string macros = solutionFiles()["10-display.glsl"] + "#define A0 1.0\n";
    for (int k = 1; k <= 24; ++k)
        macros += "#define A" + std::to_string(k) + " A" + std::to_string(k - 1) + " + A" + std::to_string(k - 1) + "\n";
    writeFolder(sub / "macro-bomb", solutionFiles({{"10-display.glsl", macros + "float bomb() { return A24; }\n"}}));
    writeText(sub / "roster.txt", "not a student\n");
    return sub;
}

}  // namespace

TEST(GradeClass, EveryStudentGetsItsMarksAndReason) {
    fs::path root = freshTempDir("grade_class");
    fs::path sub = buildClass(root), out = root / "out";
    CommandResult run = runRaylab(gradeArgs(sub, out));
    ASSERT_EQ(run.status, 0) << run.output;

    // grades.csv: a header, then every student exactly once, sorted, the total last.
    std::vector<std::string> csv = lines(readText(out / "grades.csv"));
    ASSERT_FALSE(csv.empty());
    // 11-environment, 12-sky-shadows: the optional exercises, each graded in its own column with weight 0 (a bonus).
    EXPECT_EQ(csv[0], "Student,01-camera,02-intersect,03-lambert,04-shadows,05-ggx,06-geometry,07-fresnel,"
                      "08-cook-torrance,09-reflections,10-display,11-environment,12-sky-shadows,Total");
    std::vector<std::string> ids;
    for (std::size_t k = 1; k < csv.size(); ++k) ids.push_back(csv[k].substr(0, csv[k].find(',')));
    std::vector<std::string> expected = {"compile-error", "corrupt", "empty", "endless", "full", "include-escape"};
    for (const std::string& m : kMutants) expected.push_back("mutant-" + m);
    for (const char* id : {"nan", "non-utf8", "oversize", "partial", "symlink", "zero", "zip-bomb", "zip-slip",
                           "zip-symlink", "zipped", "messy-repo", "renamed", "while-true", "runaway-bound",
                           "runaway-break", "nested-zips", "folder-named", "macro-bomb"})
        expected.push_back(id);
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(ids, expected) << readText(out / "grades.csv");
    EXPECT_TRUE(contains(run.output, "roster.txt")) << "the stray file is reported as ignored";
    std::string index = readText(out / "index.html");
    // Every student on the report: the id itself, or (over 24 characters) its start and the whole in the tooltip.
    for (const std::string& id : expected)
        EXPECT_TRUE(contains(index, ">" + id + "</a>") || contains(index, "title=\"" + id + "\"><a href")) << id;

    Student full = load(out, "full");
    EXPECT_DOUBLE_EQ(full.score, 100);
    expectOthersFull(full, "full", {});
    // The budget is 10 s per complete submission on 2 cores (measured in
    // docs/grading.md); this bound only catches a grader gone much slower
    // (serialised, waiting on something), not a busy test machine.
    EXPECT_LT(full.seconds, 30);

    // Every shape of a real upload earns what its files deserve, and says which files were graded.
    for (const char* id : {"messy-repo", "renamed"}) {
        Student s = load(out, id);
        EXPECT_DOUBLE_EQ(s.score, 100) << id;
        expectOthersFull(s, id, {});
    }
    std::string messyNotes, renamedNotes;
    for (const std::string& n : load(out, "messy-repo").notes) messyNotes += n + "\n";
    for (const std::string& n : load(out, "renamed").notes) renamedNotes += n + "\n";
    EXPECT_TRUE(contains(messyNotes, "graded the folder raylab-main/exercises/")) << messyNotes;
    EXPECT_TRUE(contains(messyNotes, "not searched: .git/, build/")) << messyNotes;
    EXPECT_TRUE(contains(renamedNotes, "graded 05-ggx (1).glsl as 05-ggx.glsl")) << renamedNotes;
    EXPECT_TRUE(contains(renamedNotes, "graded 07-fresnel.GLSL as 07-fresnel.glsl")) << renamedNotes;
    EXPECT_TRUE(contains(renamedNotes, "byte-order mark")) << renamedNotes;
    Student nested = load(out, "nested-zips");
    EXPECT_DOUBLE_EQ(nested.score, 100);
    std::string nestedNotes;
    for (const std::string& n : nested.notes) nestedNotes += n + "\n";
    EXPECT_TRUE(contains(nestedNotes, "graded the folder hand-in/inner.zip/Desktop/graphics/hw/raylab/exercises/"))
        << nestedNotes;
    Student folderNamed = load(out, "folder-named");
    EXPECT_DOUBLE_EQ(folderNamed.score, 90);
    EXPECT_EQ(folderNamed.exercises.at("06-geometry").status, "NOT STARTED");
    std::string folderNotes;
    for (const std::string& n : folderNamed.notes) folderNotes += n + "\n";
    EXPECT_TRUE(contains(folderNotes, "06-geometry.glsl is a folder, not a file")) << folderNotes;
    expectOthersFull(folderNamed, "folder-named", {"06-geometry"});
    // A macro bomb: the same verdict in every run (decided before compiling), with its reason.
    Student bomb = load(out, "macro-bomb");
    EXPECT_EQ(bomb.exercises.at("10-display").status, "REFUSED");
    EXPECT_TRUE(contains(bomb.exercises.at("10-display").message, "expands to more than a million tokens"))
        << bomb.exercises.at("10-display").message;
    EXPECT_DOUBLE_EQ(bomb.score, 90);

    Student zero = load(out, "zero");
    EXPECT_DOUBLE_EQ(zero.score, 0);
    for (const auto& [exercise, g] : zero.exercises) EXPECT_EQ(g.status, "NOT STARTED") << exercise;

    for (const std::string& m : kMutants) {
        std::string id = "mutant-" + m, exercise = m.substr(0, m.find("--"));
        Student s = load(out, id);
        const Graded& g = s.exercises.at(exercise);
        EXPECT_EQ(g.status, "FAIL") << id;
        EXPECT_GT(g.points, 0) << id << ": a typical mistake earns partial credit";
        EXPECT_LT(g.points, g.maxPoints) << id;
        EXPECT_TRUE(contains(g.feedback, mutantCaughtBy(m))) << id << " should say \"" << mutantCaughtBy(m)
                                                             << "\":\n" << g.feedback;
        expectOthersFull(s, id, {exercise});
    }

    Student compile = load(out, "compile-error");
    EXPECT_EQ(compile.exercises.at("05-ggx").status, "COMPILE ERROR");
    EXPECT_TRUE(contains(compile.exercises.at("05-ggx").message, "05-ggx.glsl:3:"))
        << compile.exercises.at("05-ggx").message;
    EXPECT_FALSE(contains(compile.exercises.at("05-ggx").feedback, out.string())) << "no instructor paths";
    EXPECT_DOUBLE_EQ(compile.score, 90);
    expectOthersFull(compile, "compile-error", {"05-ggx"});

    Student endless = load(out, "endless");
    const Graded& loop = endless.exercises.at("10-display");
    EXPECT_EQ(loop.status, "TIMEOUT") << loop.message;
    EXPECT_DOUBLE_EQ(loop.points, 0);
    EXPECT_LT(loop.seconds, kTimeout + 2) << "the endless loop costs its timeout, no more";
    EXPECT_LT(endless.seconds, kTimeout + full.seconds + 10);
    Student whileTrue = load(out, "while-true");
    EXPECT_EQ(whileTrue.exercises.at("10-display").status, "TIMEOUT");
    EXPECT_TRUE(contains(whileTrue.exercises.at("10-display").message, "this loop never ends"))
        << whileTrue.exercises.at("10-display").message;
    EXPECT_DOUBLE_EQ(whileTrue.score, 90);
    // Real work in every iteration (256 sines): the guard bounds the loop at
    // 16384 iterations per probe case, which takes llvmpipe longer than the
    // timeout on this machine; a fast one may reach the bound first. Either
    // way the reason names what happened: the shader's time, or the loop.
    EXPECT_TRUE(contains(loop.message, "(shader time)") || contains(loop.message, "a loop in 10-display.glsl:"))
        << loop.message;
    EXPECT_FALSE(contains(loop.message, "compiler")) << loop.message;
    for (const auto& [id, text] : runawayLoops()) {
        Student s = load(out, id);
        const Graded& g = s.exercises.at("10-display");
        EXPECT_EQ(g.status, "TIMEOUT") << id << ": " << g.message;
        EXPECT_TRUE(contains(g.message, "a loop in 10-display.glsl:" + std::to_string(toneMapBodyLine()) +
                                            " ran more than 16384 iterations"))
            << id << ": " << g.message;
        EXPECT_DOUBLE_EQ(s.score, 90) << id;
        expectOthersFull(s, id, {"10-display"});
    }
    expectOthersFull(endless, "endless", {"10-display"});

    Student nan = load(out, "nan");
    const Graded& lambert = nan.exercises.at("03-lambert");
    EXPECT_EQ(lambert.status, "FAIL");
    EXPECT_TRUE(contains(lower(lambert.feedback), "nan")) << lambert.feedback;
    for (const json& image : lambert.record.at("images")) EXPECT_GT(image.at("non_finite").get<long>(), 0);
    EXPECT_LE(lambert.points, lambert.maxPoints / 2) << "NaN renders earn no image credit";
    expectOthersFull(nan, "nan", {"03-lambert"});

    Student escape = load(out, "include-escape");
    EXPECT_EQ(escape.exercises.at("05-ggx").status, "COMPILE ERROR");
    EXPECT_TRUE(contains(escape.exercises.at("05-ggx").message, "refused")) << escape.exercises.at("05-ggx").message;
    EXPECT_DOUBLE_EQ(escape.score, 90);

    Student link = load(out, "symlink");
    EXPECT_EQ(link.exercises.at("05-ggx").status, "REFUSED");
    EXPECT_TRUE(contains(link.exercises.at("05-ggx").message, "symbolic link"));
    EXPECT_DOUBLE_EQ(link.score, 90);
    EXPECT_FALSE(fs::exists(out / "symlink" / "submission" / "05-ggx.glsl")) << "the link is never copied";

    Student empty = load(out, "empty");
    EXPECT_DOUBLE_EQ(empty.score, 0);
    ASSERT_FALSE(empty.notes.empty());
    EXPECT_TRUE(contains(empty.notes[0], "empty"));
    for (const auto& [exercise, g] : empty.exercises) {
        EXPECT_EQ(g.status, "NOT STARTED");
        EXPECT_TRUE(contains(g.message, "empty")) << g.message;
    }

    Student latin1 = load(out, "non-utf8");
    EXPECT_EQ(latin1.exercises.at("03-lambert").status, "REFUSED");
    EXPECT_TRUE(contains(latin1.exercises.at("03-lambert").message, "03-lambert.glsl:2: file is not UTF-8 text: byte 0xE9"))
        << latin1.exercises.at("03-lambert").message;
    EXPECT_DOUBLE_EQ(latin1.score, 92);

    Student big = load(out, "oversize");
    EXPECT_EQ(big.exercises.at("05-ggx").status, "REFUSED");
    EXPECT_TRUE(contains(big.exercises.at("05-ggx").message, "over the 256 KiB limit"))
        << big.exercises.at("05-ggx").message;
    EXPECT_DOUBLE_EQ(big.score, 90);

    Student partial = load(out, "partial");
    EXPECT_DOUBLE_EQ(partial.score, 26);
    EXPECT_EQ(partial.exercises.at("05-ggx").status, "NOT STARTED");
    EXPECT_EQ(partial.exercises.at("05-ggx").message, "05-ggx.glsl is missing");
    EXPECT_TRUE(contains(partial.notes.empty() ? "" : partial.notes.back(), "README.md")) << "extra files: ignored";

    Student zipped = load(out, "zipped");
    EXPECT_DOUBLE_EQ(zipped.score, 100);
    EXPECT_TRUE(contains(zipped.notes.empty() ? "" : zipped.notes[0], "exercises/"));

    for (const auto& [id, reason] : std::map<std::string, std::string>{{"corrupt", "not a valid zip archive"},
                                                                      {"zip-slip", "climbs out"},
                                                                      {"zip-bomb", "compression ratio"}}) {
        Student s = load(out, id);
        EXPECT_DOUBLE_EQ(s.score, 0) << id;
        for (const auto& [exercise, g] : s.exercises) {
            EXPECT_EQ(g.status, "REFUSED") << id;
            EXPECT_TRUE(contains(g.message, reason)) << id << ": " << g.message;
        }
    }
    EXPECT_FALSE(fs::exists(root / "evil.glsl"));
    EXPECT_FALSE(fs::exists(out / "evil.glsl"));
    Student zipLink = load(out, "zip-symlink");
    EXPECT_EQ(zipLink.exercises.at("05-ggx").status, "REFUSED");
    EXPECT_TRUE(contains(zipLink.exercises.at("05-ggx").message, "symbolic link"));
    EXPECT_DOUBLE_EQ(zipLink.score, 90);

    json summary = readJson(out / "summary.json");
    EXPECT_EQ(summary.at("students").get<int>(), int(expected.size()));
    EXPECT_EQ(summary.at("timeouts").get<int>(), 4);
    EXPECT_EQ(summary.at("compile_errors").get<int>(), 2);
    EXPECT_EQ(summary.at("full_marks").get<int>(), 5);  // full, zipped, messy-repo, renamed, nested-zips
    if (!HasFailure()) fs::remove_all(root);
}

TEST(GradeRun, SecondRunSkipsForceRegradesAndBytesAgree) {
    fs::path root = freshTempDir("grade_resume");
    fs::path sub = root / "submissions", out = root / "out";
    writeFolder(sub / "full", solutionFiles());
    writeFolder(sub / "fresnel", solutionFiles({{"07-fresnel.glsl", mutantText("07-fresnel--power-on-voh")}}));
    writeFolder(sub / "nan", solutionFiles({{"03-lambert.glsl", nanLambert()}}));
    writeFolder(sub / "display", solutionFiles({{"10-display.glsl", mutantText("10-display--gamma-before-tonemap")}}));
    writeText(sub / "corrupt.zip", "not a zip");
    fs::create_directories(sub / "empty");

    CommandResult first = runRaylab(gradeArgs(sub, out));
    ASSERT_EQ(first.status, 0) << first.output;
    const std::string csv = readText(out / "grades.csv");
    auto stamp = fs::last_write_time(out / "full" / "grade.json");

    CommandResult again = runRaylab(gradeArgs(sub, out));
    ASSERT_EQ(again.status, 0) << again.output;
    EXPECT_TRUE(contains(again.output, "graded 0, skipped 6")) << again.output;
    EXPECT_EQ(fs::last_write_time(out / "full" / "grade.json"), stamp) << "a graded student is not graded again";
    EXPECT_EQ(readText(out / "grades.csv"), csv);

    // An interrupted run leaves no record for the student it was grading: only that one is graded again.
    fs::remove(out / "nan" / "grade.json");
    CommandResult resumed = runRaylab(gradeArgs(sub, out));
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    EXPECT_TRUE(contains(resumed.output, "graded 1, skipped 5")) << resumed.output;
    EXPECT_EQ(readText(out / "grades.csv"), csv);

    CommandResult forced = runRaylab(gradeArgs(sub, out, "--force"));
    ASSERT_EQ(forced.status, 0) << forced.output;
    EXPECT_TRUE(contains(forced.output, "graded 6, skipped 0")) << forced.output;
    EXPECT_NE(fs::last_write_time(out / "full" / "grade.json"), stamp);
    EXPECT_EQ(readText(out / "grades.csv"), csv) << "same inputs, same grades.csv";

    // A fresh output folder, one job at a time: the same bytes again.
    CommandResult serial = runRaylab("grade " + sub.string() + " -o " + (root / "out2").string() +
                                     " --jobs 1 --timeout " + std::to_string(kTimeout));
    ASSERT_EQ(serial.status, 0) << serial.output;
    EXPECT_EQ(readText(root / "out2" / "grades.csv"), csv);

    // A resubmission is noticed: only the student whose files changed is graded again.
    writeFolder(sub / "fresnel", solutionFiles());
    CommandResult changed = runRaylab(gradeArgs(sub, out));
    ASSERT_EQ(changed.status, 0) << changed.output;
    EXPECT_TRUE(contains(changed.output, "graded 1, skipped 5")) << changed.output;
    EXPECT_TRUE(contains(readText(out / "grades.csv"), "\nfresnel,8.00,10.00,8.00,10.00,10.00,10.00,8.00,14.00,12.00,10.00,0.00,0.00,100.00\n"))
        << readText(out / "grades.csv");
    if (!HasFailure()) fs::remove_all(root);
}

// A run killed outright (SIGKILL: no handler runs, the pool's workers are
// left to finish or die) and started again grades only who is missing and
// writes the same bytes as a run that was never interrupted.
TEST(GradeRun, ARunKilledOutrightResumesToTheSameBytes) {
    fs::path root = freshTempDir("grade_sigkill");
    fs::path sub = root / "submissions";
    writeFolder(sub / "full", solutionFiles());
    writeFolder(sub / "fresnel", solutionFiles({{"07-fresnel.glsl", mutantText("07-fresnel--power-on-voh")}}));
    writeFolder(sub / "display", solutionFiles({{"10-display.glsl", mutantText("10-display--gamma-before-tonemap")}}));
    writeFolder(sub / "stubs", {});
    // The same folder name for both runs, so that nothing differs but the interruption.
    fs::path whole = root / "a" / "out", killed = root / "b" / "out";
    CommandResult reference = runRaylab(gradeArgs(sub, whole));
    ASSERT_EQ(reference.status, 0) << reference.output;

    // Killed once the first student's record is written (at most 60 s of waiting).
    CommandResult kill = runShell("cd " + root.string() + " && (" + std::string(RAYLAB_BINARY) + " " +
                                  gradeArgs(sub, killed) +
                                  " >/dev/null 2>&1 & pid=$!; for i in $(seq 600); do "
                                  "ls " + killed.string() + "/*/grade.json >/dev/null 2>&1 && break; sleep 0.1; done; "
                                  "kill -9 $pid; wait $pid; echo killed $?)");
    ASSERT_TRUE(contains(kill.output, "killed 137")) << kill.output;

    CommandResult resumed = runRaylab(gradeArgs(sub, killed));
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    EXPECT_FALSE(contains(resumed.output, "graded 4, skipped 0")) << "nothing kept from the killed run: " << resumed.output;
    for (const char* name : {"grades.csv", "index.html", "gradescope-results.json"}) {
        if (!fs::exists(whole / name)) continue;
        EXPECT_EQ(readText(killed / name), readText(whole / name)) << name;
    }
    // summary.json also says what this run did (who it graded, how long it took): the rest is the same.
    json a = readJson(killed / "summary.json"), b = readJson(whole / "summary.json");
    for (json* j : {&a, &b})
        for (const char* key : {"seconds", "graded_this_run", "skipped_already_graded"}) j->erase(key);
    EXPECT_EQ(a.dump(2), b.dump(2));
    if (!HasFailure()) fs::remove_all(root);
}

// The run's shader cache (OUT/.shader-cache) holds compiled code keyed by
// the whole source, never a result: swap two students' files and run again
// over the same OUT, with the cache warm, and each gets what the files now
// deserve.
TEST(GradeRun, TheRunsShaderCacheCannotCarryResultsBetweenStudents) {
    fs::path root = freshTempDir("grade_cache");
    fs::path sub = root / "submissions", out = root / "out";
    const std::string mutant = "05-ggx--missing-pi";
    auto assign = [&](const std::string& who) {
        fs::remove_all(sub);
        writeFolder(sub / who, solutionFiles());
        writeFolder(sub / (who == "ann" ? "bob" : "ann"), solutionFiles({{"05-ggx.glsl", mutantText(mutant)}}));
    };
    assign("ann");  // ann full, bob the mutant
    writeText(root / "rubric.json", "{\"exercises\": [{\"id\": \"05-ggx\", \"weight\": 10}]}");
    CommandResult first = runRaylab(gradeArgs(sub, out, "--rubric " + (root / "rubric.json").string()));
    ASSERT_EQ(first.status, 0) << first.output;
    ASSERT_TRUE(fs::is_directory(out / ".shader-cache"));
    EXPECT_FALSE(fs::is_empty(out / ".shader-cache")) << "the run filled its cache";
    EXPECT_DOUBLE_EQ(load(out, "ann").score, 10);
    EXPECT_LT(load(out, "bob").score, 10);
    assign("bob");  // now bob full, ann the mutant: both resubmitted, graded again over the warm cache
    CommandResult second = runRaylab(gradeArgs(sub, out, "--rubric " + (root / "rubric.json").string()));
    ASSERT_EQ(second.status, 0) << second.output;
    EXPECT_DOUBLE_EQ(load(out, "bob").score, 10);
    EXPECT_LT(load(out, "ann").score, 10);
    EXPECT_EQ(load(out, "ann").exercises.at("05-ggx").status, "FAIL");
    if (!HasFailure()) fs::remove_all(root);
}

// A student's check scenes are drawn once with every file whose probes pass
// (checkExercises(), docs/grading.md "Scale"), and an exercise draws its own
// only where that picture is not within the budget: a complete submission
// written differently from solutions/ (the course's alternatives) takes the
// shared pictures and full marks; a file whose probes pass but whose picture
// is wrong (10-display blacking out all but the first rows: the probes' grid
// is one or two rows high) fails its images alone, and every other exercise
// earns its marks from its own ray tracer, with the solution's 10-display.
TEST(GradeRun, TheWholeSubmissionIsDrawnOnceAndAWrongPictureByEachFile) {
    fs::path root = freshTempDir("grade_whole");
    fs::path sub = root / "submissions", out = root / "out";
    std::map<std::string, std::string> alternatives;  // the first of each required exercise's (sorted)
    for (const std::string& name : unitFileNames("alternatives")) {
        const std::string exercise = name.substr(0, name.find("--"));
        if (std::count(kAll.begin(), kAll.end(), exercise) && !alternatives.count(exercise + ".glsl"))
            alternatives[exercise + ".glsl"] = readText(unitFilePath("alternatives", name));
    }
    ASSERT_GE(alternatives.size(), 6u) << "the course's alternatives";
    writeFolder(sub / "alternatives", solutionFiles(alternatives));
    std::string display = solutionFiles()["10-display.glsl"];
    const std::string head = "vec3 toneMap(vec3 c, int op) {\n";
    ASSERT_NE(display.find(head), std::string::npos);
    display.insert(display.find(head) + head.size(), "    if (gl_FragCoord.y > 24.0) return vec3(0.0);\n");
    writeFolder(sub / "picture-only", solutionFiles({{"10-display.glsl", display}}));
    CommandResult run = runRaylab(gradeArgs(sub, out));
    ASSERT_EQ(run.status, 0) << run.output;

    auto images = [](const Graded& g) { return g.record.at("images"); };
    Student alt = load(out, "alternatives");
    EXPECT_DOUBLE_EQ(alt.score, 100);
    expectOthersFull(alt, "alternatives", {});
    for (const std::string& exercise : kAll)
        for (const json& image : images(alt.exercises.at(exercise)))
            EXPECT_EQ(image.at("got").get<std::string>(), "images/all-files/" + image.at("scene").get<std::string>() + "-got.png")
                << exercise << ": the whole submission's picture";
    EXPECT_FALSE(fs::exists(out / "alternatives" / "images" / "05-ggx")) << "no exercise drew its own";

    Student wrong = load(out, "picture-only");
    const Graded& shown = wrong.exercises.at("10-display");
    EXPECT_EQ(shown.status, "FAIL") << shown.message;
    EXPECT_DOUBLE_EQ(shown.record.at("probe_fraction").get<double>(), 1.0);
    EXPECT_LT(shown.record.at("image_fraction").get<double>(), 1.0);
    EXPECT_TRUE(contains(shown.message, "of pixels off")) << shown.message;
    expectOthersFull(wrong, "picture-only", {"10-display"});
    for (const std::string& exercise : kAll) {
        int own = 0;
        for (const json& image : images(wrong.exercises.at(exercise)))
            own += image.at("got").get<std::string>().rfind("images/" + exercise + "/", 0) == 0;
        EXPECT_GT(own, 0) << exercise << ": a scene the whole submission fails is drawn by the exercise's own ray tracer";
    }
    if (!HasFailure()) fs::remove_all(root);
}

TEST(GradeRun, ShardsMergeToTheUnshardedGrades) {
    fs::path root = freshTempDir("grade_shards");
    fs::path sub = root / "submissions";
    std::vector<std::string> ids = {"ada", "bob", "cy", "dee", "eve", "fay"};
    writeFolder(sub / "ada", solutionFiles());
    writeFolder(sub / "bob", stubFiles());
    writeFolder(sub / "cy", solutionFiles({{"10-display.glsl", mutantText("10-display--pow-gamma")}}));
    writeFolder(sub / "dee", solutionFiles({{"05-ggx.glsl", compileErrorGgx()}}));
    writeFolder(sub / "eve", solutionFiles({{"06-geometry.glsl", mutantText("06-geometry--ibl-k")}}));
    std::vector<ZipEntry> zipped;
    for (const auto& [name, text] : solutionFiles({{"04-shadows.glsl", mutantText("04-shadows--no-offset")}}))
        zipped.push_back({name, text});
    writeZip(sub / "fay.zip", zipped);
    std::set<int> slices;
    for (const std::string& id : ids) slices.insert(rl::shardOf(id, 2));
    ASSERT_EQ(slices.size(), 2u) << "both shards get students";

    CommandResult whole = runRaylab(gradeArgs(sub, root / "whole"));
    ASSERT_EQ(whole.status, 0) << whole.output;
    for (const char* shard : {"1/2", "2/2"}) {
        std::string dir = std::string("shard") + shard[0];
        CommandResult part = runRaylab(gradeArgs(sub, root / dir, std::string("--shard ") + shard));
        ASSERT_EQ(part.status, 0) << part.output;
    }
    EXPECT_LT(lines(readText(root / "shard1" / "grades.csv")).size(), ids.size() + 1);

    CommandResult lonely = runRaylab("grade merge " + (root / "shard1").string() + " -o " + (root / "bad").string());
    EXPECT_NE(lonely.status, 0);
    EXPECT_TRUE(contains(lonely.output, "shard 2/2 is missing")) << lonely.output;

    CommandResult merged = runRaylab("grade merge " + (root / "shard1").string() + " " + (root / "shard2").string() +
                                     " -o " + (root / "merged").string());
    ASSERT_EQ(merged.status, 0) << merged.output;
    EXPECT_EQ(readText(root / "merged" / "grades.csv"), readText(root / "whole" / "grades.csv"));
    for (const std::string& id : ids) EXPECT_TRUE(fs::exists(root / "merged" / id / "index.html")) << id;
    if (!HasFailure()) fs::remove_all(root);
}

TEST(GradeRun, HtmlReportRendersInHeadlessChromium) {
    fs::path root = freshTempDir("grade_html");
    fs::path sub = root / "submissions", out = root / "out";
    writeFolder(sub / "full", solutionFiles());
    writeFolder(sub / "fresnel", solutionFiles({{"07-fresnel.glsl", mutantText("07-fresnel--one-plus-f0")}}));
    writeFolder(sub / "broken", solutionFiles({{"05-ggx.glsl", compileErrorGgx()}}));
    writeFolder(sub / "a b&<c>", stubFiles());  // an id that needs escaping in HTML and in URLs
    writeText(sub / "corrupt.zip", "not a zip");
    writeText(sub / "notes.txt", "not a student");  // issue 22: listed at the top of the report
    CommandResult run = runRaylab(gradeArgs(sub, out));
    ASSERT_EQ(run.status, 0) << run.output;

    std::string index = readText(out / "index.html");
    for (const char* id : {"full", "fresnel", "broken", "corrupt"}) EXPECT_TRUE(contains(index, id)) << id;
    EXPECT_TRUE(contains(index, "a b&amp;&lt;c&gt;"));
    EXPECT_TRUE(contains(index, "href=\"a%20b%26%3Cc%3E/index.html\""));
    EXPECT_TRUE(fs::exists(out / "a b&<c>" / "index.html"));
    // Opens from the file system: nothing from the network.
    std::regex remote(R"((src|href)\s*=\s*"(https?:)?//)");
    for (const fs::path& page : {out / "index.html", out / "fresnel" / "index.html"})
        EXPECT_FALSE(std::regex_search(readText(page), remote)) << page;

    // Every image the student's page shows exists: their render, the reference, the heat map.
    std::string page = readText(out / "fresnel" / "index.html");
    std::regex img("<img src=\"([^\"]+)\"");
    int images = 0;
    for (auto it = std::sregex_iterator(page.begin(), page.end(), img); it != std::sregex_iterator(); ++it, ++images)
        EXPECT_TRUE(fs::is_regular_file(out / "fresnel" / (*it)[1].str())) << (*it)[1].str();
    EXPECT_EQ(images, 12 * 5 * 3) << "every check scene of every exercise (the optional 11 and 12 too): render, reference, difference";
    EXPECT_TRUE(contains(readText(out / "broken" / "index.html"), "05-ggx.glsl:3:")) << "the compile log, file:line";

    const std::string chromium = "timeout 120 chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
                                 "--disable-background-networking --disable-component-update --disable-sync ";
    for (int width : {1280, 1920})
        for (const auto& [name, file] : std::map<std::string, fs::path>{{"index", out / "index.html"},
                                                                        {"student", out / "fresnel" / "index.html"}}) {
            const std::string tag = name + "-" + std::to_string(width);
            fs::path shot = root / (tag + ".png");
            std::string command = chromium + "--user-data-dir=" + (root / ("chromium-" + tag)).string() +
                                  " --screenshot=" + shot.string() + " --window-size=" + std::to_string(width) +
                                  ",900 'file://" + file.string() + "' > /dev/null 2>&1";
            EXPECT_EQ(std::system(command.c_str()), 0) << command;
            ASSERT_TRUE(fs::exists(shot)) << command;
            EXPECT_GT(fs::file_size(shot), 1000u);
            rl::DisplayImage picture = rl::readPng(shot.string());
            EXPECT_EQ(picture.width, width);
            std::set<int> colours;
            for (std::size_t k = 0; k + 2 < picture.rgb.size() && colours.size() < 8; k += 3 * 97)
                colours.insert(picture.rgb[k] << 16 | picture.rgb[k + 1] << 8 | picture.rgb[k + 2]);
            EXPECT_GE(colours.size(), 4u) << tag << ": the screenshot shows a page, not a blank";
        }

    // The reason at a glance: a short one in each cell, the whole one in its tooltip.
    EXPECT_TRUE(std::regex_search(index, std::regex("title=\"FAIL: [^\"]+\">[0-9.]+<span class=\"why\">probes "))) << index;
    EXPECT_TRUE(contains(index, "<span class=\"why\">05-ggx.glsl:3</span>")) << "the compile error's file:line";
    // Failures first on the student's page, the passes folded away below them.
    std::smatch h2;
    ASSERT_TRUE(std::regex_search(page, h2, std::regex("<h2 id=\"([^\"]+)\"")));
    EXPECT_EQ(h2[1].str(), "07-fresnel") << "the failing exercise first";
    EXPECT_TRUE(contains(page, "<details class=\"passed\"><summary>11 exercises passed:")) << page.substr(0, 3000);

    // Layout and filter as Chromium lays the page out at 1280 px: the table, notes column included,
    // fits the window, and typing in the filter box keeps the matching students only.
    std::string probe = index;
    probe.replace(probe.rfind("</body>"), 7,
                  "<script>var t = document.getElementById('grades').getBoundingClientRect();"
                  "var notes = document.querySelector('#grades td.notecol').getBoundingClientRect();"
                  "document.body.setAttribute('data-fit', String(t.right <= window.innerWidth && "
                  "notes.right <= window.innerWidth && document.documentElement.scrollWidth <= window.innerWidth));"
                  "var box = document.getElementById('filter'); box.value = 'ggx.glsl:3';"
                  "box.dispatchEvent(new Event('input'));"
                  "document.body.setAttribute('data-shown', document.getElementById('shown').textContent);"
                  // Issue 22: what was not graded is on the first screen; the class's mistakes fit the width.
                  "var ng = document.getElementById('not-graded').getBoundingClientRect();"
                  "document.body.setAttribute('data-not-graded', String(ng.bottom <= 900 && ng.right <= window.innerWidth));"
                  "var cm = document.getElementById('class-mistakes');"
                  "document.body.setAttribute('data-mistakes', String(!!cm && cm.getBoundingClientRect().right <= "
                  "window.innerWidth));</script></body>");
    writeText(out / "probe.html", probe);
    std::string probeDom = (root / "probe-dom.html").string();
    std::string layout = chromium + "--user-data-dir=" + (root / "chromium-probe").string() +
                         " --window-size=1280,900 --dump-dom 'file://" + (out / "probe.html").string() + "' > " +
                         probeDom + " 2>/dev/null";
    EXPECT_EQ(std::system(layout.c_str()), 0) << layout;
    std::string laidOut = readText(probeDom);
    EXPECT_TRUE(contains(laidOut, "data-fit=\"true\"")) << "the table is wider than 1280 px: " << laidOut.substr(0, 600);
    EXPECT_TRUE(contains(laidOut, "data-shown=\"1 shown\"")) << laidOut.substr(0, 600);
    EXPECT_TRUE(contains(laidOut, "data-not-graded=\"true\"")) << laidOut.substr(0, 600);
    EXPECT_TRUE(contains(laidOut, "data-mistakes=\"true\"")) << laidOut.substr(0, 600);

    // Sorting: the same page with two clicks on the Total header, as Chromium leaves the DOM.
    std::string clicked = index;
    clicked.replace(clicked.rfind("</body>"), 7,
                    "<script>var th = document.querySelectorAll('#grades th');"
                    "th[th.length - 3].click(); th[th.length - 3].click();</script></body>");
    writeText(out / "sorted.html", clicked);
    std::string dom = root / "sorted-dom.html";
    std::string dump = chromium + "--user-data-dir=" +
                       (root / "chromium-dom").string() + " --dump-dom 'file://" + (out / "sorted.html").string() +
                       "' > " + dom + " 2>/dev/null";
    EXPECT_EQ(std::system(dump.c_str()), 0) << dump;
    std::string sorted = readText(dom);
    EXPECT_TRUE(contains(sorted, "aria-sort=\"descending\"")) << sorted.substr(0, 2000);
    std::regex firstRow("<tbody>\\s*<tr[^>]*><td class=\"l id\"><a href=\"[^\"]*\">([^<]*)</a>");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(sorted, m, firstRow)) << sorted.substr(0, 2000);
    EXPECT_EQ(m[1].str(), "full") << "the highest total first";
    if (!HasFailure()) fs::remove_all(root);
}

// Gradescope's documented results.json fields (gradescope-autograders.readthedocs.io/en/latest/specs/).
void expectGradescopeResults(const json& results) {
    static const std::set<std::string> top = {"score", "execution_time", "output", "output_format", "test_output_format",
                                              "test_name_format", "visibility", "stdout_visibility", "extra_data",
                                              "tests", "leaderboard"};
    static const std::set<std::string> perTest = {"score", "max_score", "status", "name", "name_format", "number",
                                                  "output", "output_format", "tags", "visibility", "extra_data"};
    static const std::set<std::string> visibilities = {"visible", "hidden", "after_due_date", "after_published"};
    static const std::set<std::string> formats = {"text", "html", "simple_format", "md", "ansi"};
    for (const auto& [key, value] : results.items()) EXPECT_TRUE(top.count(key)) << "not a documented field: " << key;
    EXPECT_TRUE(results.at("score").is_number());
    EXPECT_TRUE(results.at("execution_time").is_number_integer());
    EXPECT_TRUE(formats.count(results.value("output_format", "text")));
    EXPECT_TRUE(formats.count(results.value("test_output_format", "text")));
    EXPECT_TRUE(visibilities.count(results.value("visibility", "visible")));
    EXPECT_TRUE(visibilities.count(results.value("stdout_visibility", "hidden")));
    double sum = 0;
    for (const json& t : results.at("tests")) {
        for (const auto& [key, value] : t.items()) EXPECT_TRUE(perTest.count(key)) << "not a documented test field: " << key;
        EXPECT_TRUE(t.at("score").is_number());
        EXPECT_TRUE(t.at("max_score").is_number());
        EXPECT_TRUE(t.at("status") == "passed" || t.at("status") == "failed");
        EXPECT_TRUE(visibilities.count(t.value("visibility", "visible")));
        EXPECT_TRUE(formats.count(t.value("output_format", "text")));
        const std::string output = t.at("output").get<std::string>();
        // Only results.json reaches Gradescope: no output may point at an image file.
        EXPECT_FALSE(contains(output, ".png")) << output;
        sum += t.at("score").get<double>();
    }
    EXPECT_NEAR(sum, results.at("score").get<double>(), 0.005);
}

TEST(GradeRun, GradescopeLayoutWritesResultsJson) {
    fs::path root = freshTempDir("grade_gradescope");
    auto three = solutionFiles();
    for (auto it = three.begin(); it != three.end();)
        it = it->first < "04" ? std::next(it) : three.erase(it);
    writeFolder(root / "submission" / "exercises", three);
    CommandResult run = runRaylab("grade --gradescope --timeout " + std::to_string(kTimeout),
                                  "RAYLAB_GRADESCOPE_ROOT=" + root.string());
    ASSERT_EQ(run.status, 0) << run.output;
    json results = readJson(root / "results" / "results.json");
    expectGradescopeResults(results);
    EXPECT_DOUBLE_EQ(results.at("score").get<double>(), 26);
    ASSERT_EQ(results.at("tests").size(), 12u);  // the ten and the optional 11-environment and 12-sky-shadows (max_score 0)
    const json& first = results["tests"][0];
    for (const char* key : {"name", "score", "max_score", "status", "output", "visibility"})
        EXPECT_TRUE(first.contains(key)) << key;
    EXPECT_EQ(first.at("status"), "passed");
    EXPECT_EQ(results["tests"][4].at("status"), "failed");
    EXPECT_TRUE(results.contains("execution_time"));

    fs::path nothing = freshTempDir("grade_gradescope_empty");
    CommandResult none = runRaylab("grade --gradescope --gradescope-root " + nothing.string());
    EXPECT_EQ(none.status, 0) << none.output;
    json empty = readJson(nothing / "results" / "results.json");
    EXPECT_DOUBLE_EQ(empty.at("score").get<double>(), 0);
    EXPECT_TRUE(contains(empty.at("output").get<std::string>(), "submission")) << empty.dump();
    if (!HasFailure()) {
        fs::remove_all(root);
        fs::remove_all(nothing);
    }
}

// The run_autograder of docs/grading.md, run as written in a temporary
// folder standing in for /autograder.
TEST(GradeRun, DocumentedRunAutograderInAFakedLayout) {
    std::string doc = readText(rl::sourceRoot() / "docs" / "grading.md");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(doc, m, std::regex("`run_autograder`:\\n\\n```bash\\n([\\s\\S]*?)```")))
        << "docs/grading.md shows run_autograder";
    const fs::path root = freshTempDir("gradescope_layout");
    std::string script = std::regex_replace(m[1].str(), std::regex("/autograder"), root.string());
    writeText(root / "run_autograder", script);
    fs::permissions(root / "run_autograder", fs::perms::owner_all);
    fs::create_directories(root / "source" / "build" / "bin");
    fs::create_symlink(RAYLAB_BINARY, root / "source" / "build" / "bin" / "raylab");
    // source/ stands for the checkout: its ./raylab wrapper, the sources read
    // from this repository (RAYLAB_ROOT below).
    fs::copy_file(rl::sourceRoot() / "raylab", root / "source" / "raylab");
    auto three = solutionFiles();
    for (auto it = three.begin(); it != three.end();)
        it = it->first < "04" ? std::next(it) : three.erase(it);
    std::vector<ZipEntry> zipped;
    for (const auto& [name, text] : three) zipped.push_back({"raylab/exercises/" + name, text});
    fs::create_directories(root / "submission");
    writeZip(root / "submission" / "upload.zip", zipped);  // what a student's zip upload looks like
    fs::create_directories(root / "results");
    std::string command = "cd " + root.string() + " && RAYLAB_GRADESCOPE_ROOT=" + root.string() +
                          " RAYLAB_ROOT=" + rl::sourceRoot().string() + " ./run_autograder > results/stdout 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << readText(root / "results" / "stdout");
    json results = readJson(root / "results" / "results.json");
    expectGradescopeResults(results);
    EXPECT_DOUBLE_EQ(results.at("score").get<double>(), 26);
    EXPECT_EQ(results.at("output_format"), "text");
    EXPECT_TRUE(contains(results.value("output", ""), "upload.zip")) << "the note says what was graded";
    if (!HasFailure()) fs::remove_all(root);
}

std::string joinedNotes(const std::vector<std::string>& notes) {
    std::string out;
    for (const std::string& n : notes) out += n + "\n";
    return out;
}

// Issue 22: the names LMS downloads hold, end to end. Before: the Unicode and
// anonymous Canvas files were skipped, the folder named with byte 0xE9 stopped
// the whole run with "internal error: [json.exception.type_error.316]" and no
// outputs, ignored entries and roster students without a submission were not
// in index.html, and an id starting with '=' reached grades.csv as a formula.
TEST(GradeRun, EveryNameShapeIsGradedOnceAndNothingDropsSilently) {
    fs::path root = freshTempDir("grade_names");
    const fs::path sub = root / "sub", out = root / "out";
    const std::string camera = solutionFiles()["01-camera.glsl"];
    fs::create_directories(sub);
    writeText(sub / "m\xC3\xBCllerj\xC3\xBCrgen_1005_70021_01-camera.glsl", camera);
    writeText(sub / "doejane_1001_70020_01-camera-1.glsl", camera);
    writeText(sub / "anon_x7Kq2_70024_01-camera.glsl", camera);
    writeFolder(sub / "caf\xE9", {{"01-camera.glsl", camera}});
    writeZip(sub / "bad\xFFname.zip", {{"01-camera.glsl", camera}});
    writeFolder(sub / "=HYPERLINK(1)", {{"01-camera.glsl", stubFiles()["01-camera.glsl"]}});
    writeFolder(sub / "cp1252", {{"01-camera.glsl", "// r\xe9sum\xe9 saved by Notepad\n" + camera}});
    writeText(sub / "notes.txt", "x");
    writeText(root / "rubric.json", "{\"exercises\": [{\"id\": \"01-camera\", \"weight\": 10}]}");
    const std::string roster = (rl::sourceRoot() / "tests" / "grading" / "fixtures" / "canvas-gradebook-export.csv").string();
    CommandResult r = runRaylab(gradeArgs(sub, out, "--rubric " + (root / "rubric.json").string() +
                                                        " --export canvas --roster " + roster));
    EXPECT_EQ(r.status, 3) << "graded, with submissions left out of the Canvas export: " << r.output;
    ASSERT_TRUE(fs::exists(out / "summary.json")) << r.output;
    const json summary = readJson(out / "summary.json");
    EXPECT_EQ(summary.at("students").get<int>(), 7) << summary.dump(2);
    std::map<std::string, double> scores;
    for (const std::string& id : lines(readText(out / "students.txt")))
        scores[id] = readJson(out / id / "results.json").at("score").get<double>();
    EXPECT_EQ(scores, (std::map<std::string, double>{{"=HYPERLINK(1)", 0},
                                                     {"anon_x7Kq2", 10},
                                                     {"bad%FFname", 10},
                                                     {"caf%E9", 10},
                                                     {"cp1252", 10},
                                                     {"doejane_1001", 10},
                                                     {"m\xC3\xBCllerj\xC3\xBCrgen_1005", 10}}));
    EXPECT_EQ(readJson(out / "caf%E9" / "grade.json").value("source_bytes", ""), "63 61 66 e9");
    EXPECT_TRUE(contains(joinedNotes(load(out, "cp1252").notes), "were read as Windows-1252"));
    // Copies of the solution are base code (issue 36): no cluster, nothing marked down.
    EXPECT_TRUE(summary.at("similar_submissions").at("clusters").empty()) << summary.at("similar_submissions").dump();
    const std::string csv = readText(out / "grades.csv");
    for (const std::string& line : lines(csv))
        EXPECT_EQ(std::string("=+-@\t\r").find(line[0]), std::string::npos) << line;
    EXPECT_TRUE(contains(csv, "\n'=HYPERLINK(1),0.00,0.00\n")) << csv;
    EXPECT_EQ(summary.at("ignored_entries").size(), 1u);
    EXPECT_EQ(summary.at("ignored_count"), 1);
    const std::string index = readText(out / "index.html");
    EXPECT_TRUE(contains(index, "id=\"not-graded\"")) << "the not-graded list is at the top of the report";
    EXPECT_LT(index.find("id=\"not-graded\""), index.find("id=\"grades\""));
    EXPECT_TRUE(contains(index, "notes.txt (a file that is not a .zip")) << index;
    EXPECT_TRUE(contains(index, "Smith, John (canvas-gradebook-export.csv line 4)")) << index;
    EXPECT_TRUE(contains(index, "anon_x7Kq2: an anonymous Canvas download")) << index;
    EXPECT_FALSE(contains(index, "Doe, Jane (canvas")) << "doejane_1001 has a submission";
    EXPECT_TRUE(contains(index, "id=\"test-student\"")) << "the Canvas Test Student's treatment is said";
    EXPECT_TRUE(contains(index, "<h2 id=\"mistakes\">What the class got wrong</h2>"));
    ASSERT_EQ(summary.at("class_mistakes").size(), 1u);
    EXPECT_EQ(summary.at("class_mistakes")[0].at("passed"), 6);
    // The second run finds every record and writes the same bytes.
    CommandResult again = runRaylab(gradeArgs(sub, out, "--rubric " + (root / "rubric.json").string()));
    EXPECT_EQ(again.status, 0) << again.output;
    EXPECT_TRUE(contains(again.output, "7 students already graded")) << again.output;
    EXPECT_EQ(readText(out / "grades.csv"), csv);
    if (!HasFailure()) fs::remove_all(root);
}

// Every option and the roster are checked before the first student: a wrong
// roster found after the class is graded costs the whole run.
TEST(GradeCli, AnExportThatCannotBeWrittenIsRefusedBeforeGrading) {
    fs::path root = freshTempDir("grade_early");
    writeFolder(root / "sub" / "alice", {{"01-camera.glsl", "// mine\n"}});
    const std::string canvasRoster = (rl::sourceRoot() / "tests" / "grading" / "fixtures" / "canvas-gradebook-export.csv").string();
    CommandResult r = runRaylab("grade " + (root / "sub").string() + " -o " + (root / "out").string() +
                                " --export moodle --roster " + canvasRoster);
    EXPECT_NE(r.status, 0);
    EXPECT_TRUE(contains(r.output, "canvas-gradebook-export.csv: a Canvas roster; the Moodle export needs")) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(root / "out" / "alice")) << "nobody was graded";
    CommandResult missing = runRaylab("grade " + (root / "sub").string() + " -o " + (root / "out").string() +
                                      " --export canvas --roster " + (root / "none.csv").string());
    EXPECT_NE(missing.status, 0);
    EXPECT_TRUE(contains(missing.output, "none.csv: roster file not found")) << missing.output;
    EXPECT_FALSE(fs::exists(root / "out" / "alice"));
    if (!HasFailure()) fs::remove_all(root);
}

TEST(GradeCli, BadArgumentsGiveOneLineAndNonZeroExit) {
    fs::path root = freshTempDir("grade_cli");
    CommandResult noArgs = runRaylab("grade");
    EXPECT_NE(noArgs.status, 0);
    EXPECT_TRUE(contains(noArgs.output, "SUBMISSIONS")) << noArgs.output;
    CommandResult missing = runRaylab("grade " + (root / "nope").string() + " -o " + (root / "out").string());
    EXPECT_NE(missing.status, 0);
    EXPECT_TRUE(contains(missing.output, "nope: not a folder of submissions")) << missing.output;
    fs::create_directories(root / "sub");
    CommandResult shard = runRaylab("grade " + (root / "sub").string() + " -o " + (root / "out").string() + " --shard 3/2");
    EXPECT_NE(shard.status, 0);
    EXPECT_TRUE(contains(shard.output, "--shard")) << shard.output;
    writeText(root / "rubric.json", "{\"exercises\": [{\"id\": \"11-teapot\", \"weight\": 5}]}");
    CommandResult rubric = runRaylab("grade " + (root / "sub").string() + " -o " + (root / "out").string() +
                                     " --rubric " + (root / "rubric.json").string());
    EXPECT_NE(rubric.status, 0);
    EXPECT_TRUE(contains(rubric.output, "rubric.json: exercises[0]: unknown exercise")) << rubric.output;
    fs::create_directories(root / "sub" / "alice");
    CommandResult inside = runRaylab("grade " + (root / "sub").string() + " -o " + (root / "sub" / "out").string());
    EXPECT_NE(inside.status, 0);
    EXPECT_TRUE(contains(inside.output, "must lie outside")) << inside.output;
    EXPECT_TRUE(fs::exists(root / "sub" / "alice")) << "a submission is never cleared";
    for (const CommandResult* r : {&noArgs, &missing, &shard, &rubric, &inside})
        EXPECT_EQ(std::count(r->output.begin(), r->output.end(), '\n'), 1) << r->output;
    if (!HasFailure()) fs::remove_all(root);
}

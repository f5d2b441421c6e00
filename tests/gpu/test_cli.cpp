// `raylab render` as a user meets it: outputs, and one clear line with a
// non-zero exit for every bad input.
#include "core/image.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace rl;

namespace {

int lines(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST(Cli, RenderWritesPngAndPfmAndPrintsTheirPaths) {
    fs::path dir = test::freshTempDir("cli_render");
    auto r = test::runRaylab("render -o " + (dir / "a.png").string() + " --hdr " + (dir / "a.pfm").string() +
                             " --size 40x30");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(r.output, (dir / "a.png").string() + "\n" + (dir / "a.pfm").string() + "\n");
    DisplayImage png = readPng((dir / "a.png").string());
    EXPECT_EQ(png.width, 40);
    EXPECT_EQ(png.height, 30);
    RadianceImage pfm = readPfm((dir / "a.pfm").string());
    EXPECT_EQ(pfm.width, 40);
    EXPECT_EQ(test::readText(dir / "a.pfm").substr(0, 3), "PF\n");
}

TEST(Cli, CpuRenderIsTheSameAsGl) {
    fs::path dir = test::freshTempDir("cli_cpu");
    ASSERT_EQ(test::runRaylab("render --size 64x48 -o " + (dir / "gl.png").string()).status, 0);
    ASSERT_EQ(test::runRaylab("render --cpu --size 64x48 -o " + (dir / "cpu.png").string()).status, 0);
    Rendering gl{{}, readPng((dir / "gl.png").string())}, cpu{{}, readPng((dir / "cpu.png").string())};
    ImageDiff d = compareRenderings(gl, cpu);
    EXPECT_LE(d.offFraction, 0.005) << test::describe(d);
}

TEST(Cli, MissingSceneFile) {
    auto r = test::runRaylab("render /nonexistent/scene.json -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, "raylab: error: /nonexistent/scene.json: scene file not found\n");
}

TEST(Cli, SceneIsADirectory) {
    fs::path dir = test::freshTempDir("cli_dir");
    auto r = test::runRaylab("render " + dir.string() + " -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, "raylab: error: " + dir.string() + ": is a directory, expected a scene file (.json)\n");
}

TEST(Cli, EmptySceneFile) {
    fs::path dir = test::freshTempDir("cli_empty");
    test::writeText(dir / "empty.json", "");
    auto r = test::runRaylab("render " + (dir / "empty.json").string() + " -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, "raylab: error: " + (dir / "empty.json").string() +
                            ": the scene file is empty (expected a JSON object)\n");
}

TEST(Cli, SyntaxErrorNamesLineAndColumn) {
    fs::path dir = test::freshTempDir("cli_syntax");
    test::writeText(dir / "x.json", "{\n  \"spheres\": [\n    { \"radius\": 1 }\n  ]\n  \"lights\": []\n}\n");
    auto r = test::runRaylab("render " + (dir / "x.json").string() + " -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output.rfind("raylab: error: " + (dir / "x.json").string() + ":5:", 0), 0u) << r.output;
    EXPECT_EQ(lines(r.output), 1) << r.output;
}

TEST(Cli, BadValueNamesTheFieldPath) {
    fs::path dir = test::freshTempDir("cli_value");
    test::writeText(dir / "x.json", R"({"spheres": [{}, {}, {}, {"radius": 0}]})");
    auto r = test::runRaylab("render " + (dir / "x.json").string() + " -o /tmp/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, "raylab: error: " + (dir / "x.json").string() + ": spheres[3].radius must be > 0\n");
}

TEST(Cli, UnknownKeyIsAWarningAndTheRenderGoesOn) {
    fs::path dir = test::freshTempDir("cli_unknown");
    test::writeText(dir / "x.json", R"({"render": {"width": 8, "height": 8, "resolution": 3}})");
    auto r = test::runRaylab("render " + (dir / "x.json").string() + " -o " + (dir / "x.png").string());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("raylab: warning: " + (dir / "x.json").string() +
                            ": unknown key 'render.resolution' (ignored)"),
              std::string::npos)
        << r.output;
    EXPECT_TRUE(fs::exists(dir / "x.png"));
}

TEST(Cli, BadOptions) {
    auto size = test::runRaylab("render --size 640by480 -o /tmp/x.png");
    EXPECT_EQ(size.status, 2);
    EXPECT_EQ(size.output, "raylab: error: --size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, e.g. 640x480, "
                           "not '640by480'\n");
    auto spp = test::runRaylab("render --spp 3 -o /tmp/x.png");
    EXPECT_EQ(spp.status, 2);
    EXPECT_NE(spp.output.find("--spp: must be a square number"), std::string::npos);
    auto impl = test::runRaylab("render --impl /nonexistent -o /tmp/x.png");
    EXPECT_EQ(impl.status, 1);
    EXPECT_EQ(impl.output, "raylab: error: --impl: /nonexistent is not a directory\n");
    auto view = test::runRaylab("render --view sparkles -o /tmp/x.png");
    EXPECT_EQ(view.status, 1);
    EXPECT_NE(view.output.find("--view: unknown view 'sparkles'"), std::string::npos);
    auto unknown = test::runRaylab("render --frobnicate");
    EXPECT_NE(unknown.status, 0);
    EXPECT_NE(unknown.output.find("frobnicate"), std::string::npos);
    auto none = test::runRaylab("");
    EXPECT_NE(none.status, 0);
}

TEST(Cli, UnwritableOutputIsOneClearError) {
    auto r = test::runRaylab("render --size 8x8 -o /nonexistent/dir/x.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output.rfind("raylab: error: /nonexistent/dir/x.png: cannot write PNG", 0), 0u) << r.output;
    EXPECT_EQ(lines(r.output), 1);
}

TEST(Cli, EveryTeachingViewRendersWithoutNaN) {
    fs::path dir = test::freshTempDir("cli_views");
    for (std::string view : {"final", "d", "g", "f", "fnv", "diffuse", "specular", "ndotl", "shadow", "normals", "bounce0",
                             "bounce1", "bounce2"}) {
        std::string pfm = (dir / (view + ".pfm")).string();
        auto r = test::runRaylab("render --size 48x36 --view " + view + " -o " + (dir / (view + ".png")).string() +
                                 " --hdr " + pfm);
        ASSERT_EQ(r.status, 0) << view << ": " << r.output;
        RadianceImage image = readPfm(pfm);
        long bad = 0;
        for (float v : image.rgb) bad += !std::isfinite(v);
        EXPECT_EQ(bad, 0) << view;
    }
}

// ---- Issue 11: hostile and careless input ------------------------------------

namespace {

// Runs raylab under `timeout` so that a hang fails the test instead of the suite.
test::CommandResult runBounded(const std::string& args) { return test::runRaylab(args, "timeout -s KILL 60"); }

bool isDevice(const fs::path& p, dev_t expected) {
    struct stat st {};
    return stat(p.c_str(), &st) == 0 && S_ISCHR(st.st_mode) && st.st_rdev == expected;
}

}  // namespace

TEST(CliHostile, OutputThatIsADeviceIsRefusedAndKept) {
    // A scratch node of /dev/full (1:7) in a temp folder: never the real /dev/full.
    fs::path dir = test::freshTempDir("cli_full");
    fs::path full = dir / "full";
    if (mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0) GTEST_SKIP() << "mknod needs root";
    auto png = runBounded("render --size 8x8 -o " + full.string());
    EXPECT_EQ(png.status, 1);
    EXPECT_EQ(png.output, "raylab: error: " + full.string() +
                              ": cannot write PNG (a character device, not a regular file; name a file to write)\n");
    EXPECT_TRUE(isDevice(full, makedev(1, 7))) << "the device node was deleted";
    auto pfm = runBounded("render --size 8x8 -o " + (dir / "a.png").string() + " --hdr " + full.string());
    EXPECT_EQ(pfm.status, 1);
    EXPECT_EQ(pfm.output, "raylab: error: " + full.string() +
                              ": cannot write PFM (a character device, not a regular file; name a file to write)\n");
    EXPECT_TRUE(isDevice(full, makedev(1, 7)));
    EXPECT_FALSE(fs::exists(dir / "a.png")) << "refused before rendering, nothing written";
}

TEST(CliHostile, OutputThatIsAFolderOrFifoIsRefusedAndKept) {
    fs::path dir = test::freshTempDir("cli_outdir");
    fs::create_directory(dir / "out.png");
    auto r = runBounded("render --size 8x8 -o " + (dir / "out.png").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.output, "raylab: error: " + (dir / "out.png").string() +
                            ": cannot write PNG (a directory, not a regular file; name a file to write)\n");
    EXPECT_TRUE(fs::is_directory(dir / "out.png"));
    ASSERT_EQ(mkfifo((dir / "out.csv").c_str(), 0600), 0);
    auto bench = runBounded("bench --size 8x8 --sweeps modes --csv " + (dir / "out.csv").string());
    EXPECT_EQ(bench.status, 1);
    EXPECT_EQ(bench.output, "raylab: error: " + (dir / "out.csv").string() +
                                ": cannot write (a FIFO, not a regular file; name a file to write)\n");
    EXPECT_TRUE(fs::is_fifo(dir / "out.csv"));
}

TEST(CliHostile, AnExistingOutputIsReplacedWholeWithNothingBeside) {
    fs::path dir = test::freshTempDir("cli_replace");
    test::writeText(dir / "a.png", "the previous picture");
    ASSERT_EQ(runBounded("render --size 8x8 -o " + (dir / "a.png").string()).status, 0);
    EXPECT_EQ(readPng((dir / "a.png").string()).width, 8);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// Issue 22: the PNG was replaced before the PFM failed; -o X --hdr X lost the
// PNG; an exposure sweep to inf rendered black frames with exit 0.
TEST(CliHostile, ThePngAndPfmOfOneRenderAreReplacedTogetherOrNotAtAll) {
    fs::path dir = test::freshTempDir("cli_pair");
    test::writeText(dir / "a.png", "the previous picture");
    test::writeText(dir / "a.pfm", "the previous radiance");
    fs::create_directory(dir / "a.pfm.raylab-part");  // the PFM cannot be written where it is written first
    auto failed = runBounded("render --size 8x8 -o " + (dir / "a.png").string() + " --hdr " + (dir / "a.pfm").string());
    EXPECT_EQ(failed.status, 1) << failed.output;
    EXPECT_EQ(test::readText(dir / "a.png"), "the previous picture") << "the PNG was replaced without its PFM";
    EXPECT_EQ(test::readText(dir / "a.pfm"), "the previous radiance");
    EXPECT_FALSE(fs::exists(dir / "a.png.raylab-part"));
    fs::remove(dir / "a.pfm.raylab-part");
    auto ok = runBounded("render --size 8x8 -o " + (dir / "a.png").string() + " --hdr " + (dir / "a.pfm").string());
    EXPECT_EQ(ok.status, 0) << ok.output;
    EXPECT_EQ(readPng((dir / "a.png").string()).width, 8);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2) << "nothing left beside";
    auto same = runBounded("render --size 8x8 -o " + (dir / "b.png").string() + " --hdr " + (dir / "b.png").string());
    EXPECT_EQ(same.status, 1);
    EXPECT_EQ(same.output, "raylab: error: --hdr: " + (dir / "b.png").string() +
                               " is also the PNG of -o: give the PFM a file of its own\n");
    EXPECT_FALSE(fs::exists(dir / "b.png"));
    auto sweep = runBounded("record --size 8x8 --frames 2 --sweep exposure:inf:1 -o " + (dir / "frames").string());
    EXPECT_EQ(sweep.status, 1) << sweep.output;
    EXPECT_NE(sweep.output.find("--sweep: FROM and TO must be finite numbers"), std::string::npos) << sweep.output;
}

TEST(CliHostile, SceneThatIsAFifoOrDeviceIsRefusedWithoutBlocking) {
    fs::path dir = test::freshTempDir("cli_fifo");
    fs::path fifo = dir / "scene.json";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    for (std::string command : {"render -o " + (dir / "x.png").string(), std::string("bench --size 8x8 --sweeps modes")}) {
        auto r = runBounded(command + " " + fifo.string());
        EXPECT_EQ(r.status, 1) << command;
        EXPECT_EQ(r.output, "raylab: error: " + fifo.string() + ": cannot read the scene file (not a regular file: a FIFO)\n")
            << command;
    }
    for (std::string device : {"/dev/zero", "/dev/urandom"}) {
        auto r = runBounded("render " + device + " -o " + (dir / "x.png").string());
        EXPECT_EQ(r.status, 1);
        EXPECT_EQ(r.output, "raylab: error: " + device +
                                ": cannot read the scene file (not a regular file: a character device)\n");
    }
}

TEST(CliHostile, SceneErrorsAreOneLineWithTheFile) {
    fs::path dir = test::freshTempDir("cli_hostile_scene");
    std::string x = (dir / "x.json").string();
    auto errorFor = [&](const std::string& text) {
        test::writeText(x, text);
        auto r = runBounded("render " + x + " --size 8x8 -o " + (dir / "x.png").string());
        EXPECT_EQ(r.status, 1) << r.output;
        EXPECT_EQ(lines(r.output), 1) << r.output;
        return r.output;
    };
    EXPECT_EQ(errorFor("{\"spheres\": " + std::string(100000, '[') + "}"),
              "raylab: error: " + x + ":1:76: values nest more than 64 deep\n");
    EXPECT_EQ(errorFor("{\n \"render\": {\"exposure\": 1e400}}"),
              "raylab: error: " + x + ":2:25: number '1e400' is out of range (at most about 1.8e308)\n");
    EXPECT_EQ(errorFor(std::string("{}\0\x01\x02garbage", 12)), "raylab: error: " + x + ":1:3: NUL byte (is this a binary file?)\n");
    EXPECT_EQ(errorFor("{\"render\": {\"tonemap\": \"" + std::string(1 << 20, 'z') + "\"}}"),
              "raylab: error: " + x + ": render.tonemap must be one of reinhard, exponential, none, not '" +
                  std::string(40, 'z') + "...' (1048576 bytes)\n");
    EXPECT_EQ(errorFor(R"({"render": {"tonemap": "\u001b[2J\nsecond line"}})"),
              "raylab: error: " + x + ": render.tonemap must be one of reinhard, exponential, none, not "
                                      "'\\x1b[2J\\nsecond line'\n");
    EXPECT_EQ(errorFor(R"({"render": {"width": 16384, "height": 16384}})"),
              "raylab: error: " + x + ": render.width x render.height is 16384x16384, 268435456 pixels, more than "
                                      "the limit of 67108864 (8192x8192)\n");
}

TEST(CliHostile, HugeUpVectorRenders) {
    fs::path dir = test::freshTempDir("cli_up");
    test::writeText(dir / "x.json", R"({"camera": {"position": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1e300, 0]}})");
    auto r = runBounded("render " + (dir / "x.json").string() + " --size 8x8 -o " + (dir / "x.png").string());
    EXPECT_EQ(r.status, 0) << r.output;
}

TEST(CliHostile, UsageErrorsAreOneLineWithStatus2) {
    struct Case {
        std::string args, expected;
    };
    const Case cases[] = {
        {"", "raylab: error: name a command: render, check, grade, bench, course, view or record (raylab --help explains them)"},
        {"bogus", "raylab: error: 'bogus' is not a command; expected render, check, grade, bench, course, view or record"},
        {"\"$(printf '\\033[31mred')\"", "raylab: error: '\\x1b[31mred' is not a command; expected render, check, grade, bench, course, view or record"},
        {"-x", "raylab: error: '-x' before a command; expected render, check, grade, bench, course, view or record first (raylab --help "
               "explains them)"},
        {"render --frobnicate", "raylab: error: The following argument was not expected: --frobnicate"},
        {"render --spp 0", "raylab: error: --spp: must be a square number from 1 to 1024 (1, 4, 9, 16, ...), not '0'"},
        {"render --spp ''", "raylab: error: --spp: must be a square number from 1 to 1024 (1, 4, 9, 16, ...), not ''"},
        {"render --spp", "raylab: error: --spp: 1 required INT:SQUARE in [1 - 1024] missing"},
        {"render --size ''", "raylab: error: --size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, e.g. 640x480, not ''"},
        {"render --size 16384x16384",
         "raylab: error: --size: 16384x16384 is 268435456 pixels, more than the limit of 67108864 (8192x8192)"},
        {"render -o ''", "raylab: error: --output: must not be empty"},
        // Issue 22: %d overflowed silently, and 2^32 + 32 rendered 32 pixels wide.
        {"render --size 4294967328x24",
         "raylab: error: --size: expected WIDTHxHEIGHT between 1x1 and 16384x16384, e.g. 640x480, not '4294967328x24'"},
        {"check --timeout -1", "raylab: error: --timeout: must be a number of seconds more than 0 and at most 86400, not '-1'"},
        {"check --timeout nan", "raylab: error: --timeout: must be a number of seconds more than 0 and at most 86400, not 'nan'"},
        {"check --timeout ''", "raylab: error: --timeout: must be a number of seconds more than 0 and at most 86400, not ''"},
        {"grade --jobs 0", "raylab: error: --jobs: must be a whole number from 1 to 256, not '0'"},
        {"grade --timeout 1e999", "raylab: error: --timeout: must be a number of seconds more than 0 and at most 86400, not '1e999'"},
        {"bench --frames 0", "raylab: error: --frames: must be a whole number from 1 to 10000, not '0'"},
        {"bench --warmup 2.5", "raylab: error: --warmup: must be a whole number from 0 to 1000, not '2.5'"},
        {"bench --reference-spp 5", "raylab: error: --reference-spp: must be a square number from 1 to 1024 (1, 4, 9, 16, ...), not '5'"},
    };
    for (const Case& c : cases) {
        auto r = runBounded(c.args);
        EXPECT_EQ(r.status, 2) << c.args << ": " << r.output;
        EXPECT_EQ(r.output, c.expected + "\n") << c.args;
    }
}

TEST(CliHostile, HelpStillPrintsAndExitsZero) {
    auto r = runBounded("render --help");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.output.find("--spp"), std::string::npos);
}

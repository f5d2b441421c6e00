// The repository's documents stand on their own: every relative link in its
// Markdown resolves inside the repository (anchors included), nothing points
// at the folders beside it, and the scene JSON Schema agrees with the loader.
#include "core/error.h"
#include "core/paths.h"
#include "core/scene_io.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using rl::test::readText;

namespace {

bool skippedFolder(const fs::path& p) {
    std::string name = p.filename().string();
    return name == ".git" || name == "node_modules" || name == "check-output" || name.rfind("build", 0) == 0 ||
           name == ".gl";
}

// Every file of the repository with one of the given endings, build folders excluded.
std::vector<fs::path> repositoryFiles(const std::set<std::string>& endings) {
    std::vector<fs::path> out;
    const fs::path root = rl::sourceRoot();
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
        if (it->is_directory() && skippedFolder(it->path())) {
            it.disable_recursion_pending();
            continue;
        }
        if (it->is_regular_file() && endings.count(it->path().extension().string())) out.push_back(it->path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// GitHub's heading anchors: lower case, punctuation other than '-' and '_'
// dropped, spaces to '-'.
std::string slug(const std::string& heading) {
    std::string out;
    for (unsigned char c : heading) {
        if (std::isalnum(c) || c == '-' || c == '_' || c >= 0x80)
            out += char(std::tolower(c));
        else if (c == ' ')
            out += '-';
    }
    return out;
}

std::string stripCodeSpans(const std::string& line) {
    std::string out;
    bool inCode = false;
    for (char c : line) {
        if (c == '`') inCode = !inCode;
        else if (!inCode) out += c;
    }
    return out;
}

struct Link {
    int line;
    std::string target;
};

// Links `[text](target)` and images `![alt](target)` outside code blocks and spans.
std::vector<Link> markdownLinks(const std::string& text) {
    std::vector<Link> links;
    std::istringstream in(text);
    std::string line;
    bool fenced = false;
    for (int n = 1; std::getline(in, line); ++n) {
        std::string trimmed = line.substr(std::min(line.find_first_not_of(' '), line.size()));
        if (trimmed.rfind("```", 0) == 0) {
            fenced = !fenced;
            continue;
        }
        if (fenced) continue;
        std::string body = stripCodeSpans(line);
        for (std::size_t at = body.find("]("); at != std::string::npos; at = body.find("](", at + 2)) {
            std::size_t end = body.find(')', at + 2);
            if (end == std::string::npos) break;
            std::string target = body.substr(at + 2, end - at - 2);
            if (auto space = target.find(' '); space != std::string::npos) target.resize(space);  // "path "title""
            links.push_back({n, target});
        }
    }
    return links;
}

std::set<std::string> headingAnchors(const std::string& text) {
    std::set<std::string> anchors;
    std::istringstream in(text);
    std::string line;
    bool fenced = false;
    while (std::getline(in, line)) {
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        if (fenced || line.empty() || line[0] != '#') continue;
        std::size_t start = line.find_first_not_of('#');
        if (start == std::string::npos || line[start] != ' ') continue;
        std::string heading = line.substr(start + 1);
        std::string base = slug(heading);
        std::string anchor = base;
        for (int i = 1; anchors.count(anchor); ++i) anchor = base + "-" + std::to_string(i);
        anchors.insert(anchor);
    }
    return anchors;
}

bool insideRepository(const fs::path& target) {
    fs::path root = fs::weakly_canonical(rl::sourceRoot());
    fs::path full = fs::weakly_canonical(target);
    auto [r, f] = std::mismatch(root.begin(), root.end(), full.begin(), full.end());
    return r == root.end();
}

std::string repoPath(const fs::path& p) { return fs::relative(p, rl::sourceRoot()).string(); }

}  // namespace

TEST(Documents, EveryRelativeLinkResolvesInsideTheRepository) {
    int checked = 0;
    for (const fs::path& md : repositoryFiles({".md"})) {
        std::string text = readText(md);
        for (const Link& link : markdownLinks(text)) {
            const std::string where = repoPath(md) + ":" + std::to_string(link.line) + ": (" + link.target + ")";
            if (link.target.empty()) {
                ADD_FAILURE() << where << " empty link";
                continue;
            }
            if (link.target.find("://") != std::string::npos || link.target.rfind("mailto:", 0) == 0) {
                ADD_FAILURE() << where << " points outside the repository";
                continue;
            }
            std::string path = link.target.substr(0, link.target.find('#'));
            std::string anchor = link.target.find('#') == std::string::npos ? "" : link.target.substr(link.target.find('#') + 1);
            fs::path target = path.empty() ? md : md.parent_path() / path;
            ++checked;
            if (!insideRepository(target)) {
                ADD_FAILURE() << where << " leaves the repository";
                continue;
            }
            if (!fs::exists(target)) {
                ADD_FAILURE() << where << " does not exist";
                continue;
            }
            if (!anchor.empty() && target.extension() == ".md" && !headingAnchors(readText(target)).count(anchor))
                ADD_FAILURE() << where << " has no heading with anchor #" << anchor;
        }
    }
    EXPECT_GT(checked, 50) << "the link scanner found too few links to be working";
}

TEST(Documents, NoFileNamesTheFoldersBesideTheRepository) {
    // The spec and style notes beside the checkout exist only for the
    // project's developers; a clone has neither.
    const std::string outside = std::string("..") + "/shared";
    for (const fs::path& file : repositoryFiles({".md", ".cpp", ".h", ".glsl", ".frag", ".vert", ".json", ".txt",
                                                 ".sh", ".py", ".cmake", ".in"})) {
        std::string text = readText(file);
        EXPECT_EQ(text.find(outside), std::string::npos) << repoPath(file) << " points at " << outside;
    }
}

// The course's table in docs/exercises/README.md is the registry's, as
// `./raylab course --markdown --from docs/exercises` prints it: between the
// two marker comments, nobody writes it by hand.
TEST(Documents, TheCourseTableIsTheRegistrys) {
    const std::string page = readText(rl::sourceRoot() / "docs" / "exercises" / "README.md");
    const std::string begin = "<!-- the course: ./raylab course --markdown --from docs/exercises -->\n";
    const std::string end = "<!-- end of the course -->";
    const std::size_t a = page.find(begin), b = page.find(end);
    ASSERT_NE(a, std::string::npos) << "docs/exercises/README.md lost the marker " << begin;
    ASSERT_NE(b, std::string::npos);
    rl::test::CommandResult r = rl::test::runRaylab("course --markdown --from docs/exercises");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(page.substr(a + begin.size(), b - a - begin.size()), r.output)
        << "run ./raylab course --markdown --from docs/exercises and put its output between the markers";
}

TEST(Documents, TheModelPageHasEverySectionOfTheContract) {
    std::string model = readText(rl::sourceRoot() / "docs/model.md");
    std::set<std::string> anchors = headingAnchors(model);
    for (const char* section : {"camera", "visibility", "direct-light", "reflection-bounces", "display", "outputs",
                                "errata-in-the-course-texts"})
        EXPECT_TRUE(anchors.count(section)) << "docs/model.md lacks a section #" << section;
}

// ---- the scene schema ------------------------------------------------------

namespace {

const fs::path kValidator = rl::sourceRoot() / "tests/docs/validate_scenes.py";

// Verdict of the JSON Schema for each file: "ok" or the reason.
std::map<std::string, std::string> schemaVerdicts(const std::vector<fs::path>& files) {
    std::string cmd = "/usr/bin/python3 '" + kValidator.string() + "' '" +
                      (rl::scenesDir() / "scene.schema.json").string() + "'";
    for (const fs::path& f : files) cmd += " '" + f.string() + "'";
    cmd += " 2>&1";
    std::map<std::string, std::string> out;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) throw std::runtime_error("cannot run " + cmd);
    char buffer[4096];
    std::string all;
    while (fgets(buffer, sizeof buffer, pipe)) all += buffer;
    int status = pclose(pipe);
    if (status != 0) throw std::runtime_error("validator failed (is python3-jsonschema installed?): " + all);
    std::istringstream lines(all);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("ok ", 0) == 0) out[line.substr(3)] = "ok";
        else if (line.rfind("invalid ", 0) == 0) {
            std::string rest = line.substr(8);
            std::size_t colon = rest.find(": ");
            out[rest.substr(0, colon)] = rest.substr(colon + 2);
        }
    }
    return out;
}

std::vector<fs::path> bundledScenes() {
    std::vector<fs::path> scenes;
    for (const fs::path& f : repositoryFiles({".json"}))
        if (repoPath(f).rfind("scenes/", 0) == 0 && f.filename() != "scene.schema.json") scenes.push_back(f);
    return scenes;
}

}  // namespace

TEST(SceneSchema, ValidatesEveryBundledSceneAndEachNamesIt) {
    std::vector<fs::path> scenes = bundledScenes();
    ASSERT_GT(scenes.size(), 30u);
    auto verdicts = schemaVerdicts(scenes);
    for (const fs::path& scene : scenes) {
        EXPECT_EQ(verdicts[scene.string()], "ok") << repoPath(scene);
        std::string text = readText(scene);
        std::string expected = "\"$schema\": \"" + fs::relative(rl::scenesDir() / "scene.schema.json", scene.parent_path()).string() + "\"";
        EXPECT_NE(text.find(expected), std::string::npos) << repoPath(scene) << " should name its schema: " << expected;
        rl::LoadedScene loaded = rl::loadSceneFile(scene.string());
        EXPECT_TRUE(loaded.warnings.empty()) << repoPath(scene) << ": " << loaded.warnings.front();
    }
}

TEST(SceneSchema, LoaderAndSchemaRejectTheSameBadScenes) {
    std::vector<fs::path> bad;
    for (const auto& e : fs::directory_iterator(rl::sourceRoot() / "tests/docs/bad-scenes")) bad.push_back(e.path());
    std::sort(bad.begin(), bad.end());
    ASSERT_GT(bad.size(), 25u);
    auto verdicts = schemaVerdicts(bad);
    for (const fs::path& scene : bad) {
        EXPECT_NE(verdicts[scene.string()], "ok") << scene.filename() << ": the schema accepts what the loader should refuse";
        EXPECT_THROW(rl::loadSceneFile(scene.string()), rl::Error) << scene.filename() << ": the loader accepts it";
    }
}

TEST(SceneSchema, AnUnknownFieldIsAnErrorInTheEditorAndAWarningFromTheLoader) {
    fs::path dir = rl::test::freshTempDir("schema-unknown");
    fs::path scene = dir / "typo.json";
    rl::test::writeText(scene, R"({"spheres": [{"material": {"roughnes": 0.2}}]})");
    EXPECT_NE(schemaVerdicts({scene})[scene.string()], "ok");
    rl::LoadedScene loaded = rl::loadSceneFile(scene.string());
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_NE(loaded.warnings[0].find("spheres[0].material.roughnes"), std::string::npos) << loaded.warnings[0];
}

TEST(SceneSchema, TheLargestValuesTheLoaderTakesPassTheSchema) {
    // The schema must not refuse what the program renders: limits at their edges.
    fs::path dir = rl::test::freshTempDir("schema-edges");
    fs::path scene = dir / "edges.json";
    rl::test::writeText(scene, R"({"$schema": "scene.schema.json",
        "camera": {"fov_y": 179, "up": [0, 2, 0]},
        "render": {"width": 16384, "height": 1, "max_bounces": 16, "spp": 1024, "ambient": 0, "gamma": "srgb",
                   "tonemap": "none", "exposure": 1e-6},
        "lights": [{"intensity": 0, "color": [0, 0, 0]}],
        "spheres": [{"radius": 1e-6, "material": {"albedo": [0, 1, 0], "roughness": 0, "metallic": 1, "ao": 0,
                     "edge_tint": [0, 0, 1]}}],
        "model": {"distribution": "beckmann", "geometry": "smith-ggx-correlated", "fresnel": "conductor",
                  "diffuse": "burley", "blinn_phong": false}})");
    EXPECT_EQ(schemaVerdicts({scene})[scene.string()], "ok");
    EXPECT_NO_THROW(rl::loadSceneFile(scene.string()));
}

#include "bench/bench_test_support.h"

#include "core/scene_io.h"
#include "gl/context.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <memory>
#include <sstream>

namespace rl::test {

void ensureHeadlessContext() {
    static std::unique_ptr<GlContext> context = createHeadlessContext(Backend::Auto);
}

Scene tinyScene(const std::filesystem::path& file) {
    Scene s = loadSceneFile(file.string()).scene;
    s.render.width = 64;
    s.render.height = 48;
    return s;
}

void expectWithinBudget(const Rendering& got, const Rendering& expected, const std::string& what) {
    ImageDiff d = compareRenderings(got, expected);
    SCOPED_TRACE(what + ": " + describe(d));
    EXPECT_LE(d.offFraction, 0.005);
    EXPECT_LT(d.meanLsb, 0.2);
    EXPECT_EQ(d.nonFinite, 0);
}

std::vector<std::string> csvFields(const std::string& line) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (char c : line) {
        if (c == '"') quoted = !quoted;
        else if (c == ',' && !quoted) out.emplace_back();
        else out.back() += c;
    }
    return out;
}

std::vector<std::map<std::string, std::string>> readCsv(const std::string& text) {
    std::vector<std::map<std::string, std::string>> out;
    std::stringstream s(text);
    std::vector<std::string> header;
    for (std::string line; std::getline(s, line);) {
        if (line.empty()) continue;
        std::vector<std::string> fields = csvFields(line);
        if (header.empty()) {
            header = fields;
            continue;
        }
        EXPECT_EQ(fields.size(), header.size()) << line;
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < header.size() && k < fields.size(); ++k) row[header[k]] = fields[k];
        out.push_back(row);
    }
    return out;
}

}  // namespace rl::test

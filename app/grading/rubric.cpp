#include "grading/rubric.h"

#include "course/exercise_registry.h"
#include "core/error.h"
#include "core/paths.h"
#include "core/json_text.h"
#include "grading/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace fs = std::filesystem;

namespace rl {

using nlohmann::json;

namespace {

long toHundredths(double points) { return std::lround(points * 100.0); }

double number(const json& j, const char* key, double fallback, const std::string& where) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_number()) throw Error(where + ": \"" + key + "\" must be a number");
    double v = j[key].get<double>();
    if (!std::isfinite(v) || v < 0) throw Error(where + ": \"" + key + "\" must be a number >= 0");
    return v;
}

std::string text(const json& j, const char* key, const std::string& fallback, const std::string& where) {
    if (!j.contains(key)) return fallback;
    if (!j[key].is_string() || j[key].get<std::string>().empty())
        throw Error(where + ": \"" + key + "\" must be a non-empty string");
    return j[key].get<std::string>();
}

const std::set<std::string> kVisibilities = {"visible", "after_due_date", "after_published", "hidden"};

std::string choice(const json& j, const char* key, const std::string& fallback, const std::set<std::string>& allowed,
                   const std::string& where) {
    std::string v = text(j, key, fallback, where);
    if (!allowed.count(v)) {
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        throw Error(where + ": \"" + key + "\" must be one of " + list + ", not \"" + v + "\"");
    }
    return v;
}

}  // namespace

long Rubric::maxHundredths() const {
    long sum = 0;
    for (const RubricExercise& e : exercises) sum += toHundredths(e.weight);
    return sum;
}

fs::path defaultRubricPath() { return sourceRoot() / "grading" / "default-rubric.json"; }

Rubric loadRubric(const fs::path& file) {
    const std::string shown = file.string();
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) throw Error(shown + ": rubric file not found");
    return rubricFromJson(parseJsonText(readWholeFile(file), shown), shown);
}

Rubric rubricFromJson(const json& j, const std::string& shown) {
    if (!j.is_object()) throw Error(shown + ": expected a JSON object");
    Rubric r;
    r.idColumn = text(j, "id_column", r.idColumn, shown);
    r.totalColumn = text(j, "total_column", r.totalColumn, shown);
    json credit = j.value("credit", json::object());
    if (!credit.is_object()) throw Error(shown + ": \"credit\" must be an object");
    const std::string where = shown + ": credit";
    r.probeWeight = number(credit, "probe_weight", r.probeWeight, where);
    r.imageWeight = number(credit, "image_weight", r.imageWeight, where);
    r.failedSceneMax = number(credit, "failed_scene_max", r.failedSceneMax, where);
    r.zeroCreditMeanLsb = number(credit, "zero_credit_mean_lsb", r.zeroCreditMeanLsb, where);
    r.failMax = number(credit, "fail_max", r.failMax, where);
    if (std::fabs(r.probeWeight + r.imageWeight - 1.0) > 1e-9)
        throw Error(where + ": probe_weight + image_weight must be 1");
    if (r.failedSceneMax > 1) throw Error(where + ": failed_scene_max must be at most 1");
    if (r.zeroCreditMeanLsb <= 0) throw Error(where + ": zero_credit_mean_lsb must be > 0");
    if (r.failMax > 1) throw Error(where + ": fail_max must be at most 1");

    json gs = j.value("gradescope", json::object());
    if (!gs.is_object()) throw Error(shown + ": \"gradescope\" must be an object");
    const std::string gsWhere = shown + ": gradescope";
    r.gradescope.outputFormat =
        choice(gs, "output_format", r.gradescope.outputFormat, {"text", "md", "html", "simple_format", "ansi"}, gsWhere);
    r.gradescope.visibility = choice(gs, "visibility", r.gradescope.visibility, kVisibilities, gsWhere);
    r.gradescope.stdoutVisibility = choice(gs, "stdout_visibility", r.gradescope.stdoutVisibility, kVisibilities, gsWhere);
    if (gs.contains("leaderboard")) {
        if (!gs["leaderboard"].is_boolean()) throw Error(gsWhere + ": \"leaderboard\" must be true or false");
        r.gradescope.leaderboard = gs["leaderboard"].get<bool>();
    }

    std::set<std::string> seen, columns{r.idColumn, r.totalColumn};
    if (!j.contains("exercises")) {
        // No list: every exercise of the course (course/manifest.txt), each
        // with its unit's weight (unit.json), in the course's order; an
        // optional one (a bonus) graded in its column with weight 0.
        for (const ExerciseInfo& e : allExercises()) {
            RubricExercise x;
            x.id = e.id;
            x.weight = e.optional ? 0 : e.weight;
            x.column = e.id;
            if (!columns.insert(x.column).second) throw Error(shown + ": column \"" + x.column + "\" is used twice");
            r.exercises.push_back(x);
        }
        if (r.maxHundredths() <= 0) throw Error(shown + ": the units' weights add up to 0");
        return r;
    }
    if (!j["exercises"].is_array() || j["exercises"].empty())
        throw Error(shown + ": \"exercises\" must be a non-empty array of {\"id\", \"weight\"} (or left out: the units' weights)");
    for (std::size_t k = 0; k < j["exercises"].size(); ++k) {
        const json& e = j["exercises"][k];
        const std::string at = shown + ": exercises[" + std::to_string(k) + "]";
        if (!e.is_object()) throw Error(at + ": expected an object {\"id\", \"weight\"}");
        RubricExercise x;
        std::string key = text(e, "id", "", at);
        if (key.empty()) throw Error(at + ": \"id\" is missing");
        try {
            x.id = findExercise(key).id;
        } catch (const Error&) {
            throw Error(at + ": unknown exercise \"" + key + "\"");
        }
        if (!seen.insert(x.id).second) throw Error(at + ": " + x.id + " is listed twice");
        if (!e.contains("weight")) throw Error(at + ": \"weight\" is missing");
        x.weight = number(e, "weight", 0, at);
        x.column = text(e, "column", x.id, at);
        x.visibility = choice(e, "visibility", x.visibility, kVisibilities, at);
        if (!columns.insert(x.column).second) throw Error(at + ": column \"" + x.column + "\" is used twice");
        r.exercises.push_back(x);
    }
    if (r.maxHundredths() <= 0) throw Error(shown + ": the weights add up to 0");
    return r;
}

json toJson(const Rubric& r) {
    json exercises = json::array();
    for (const RubricExercise& e : r.exercises)
        exercises.push_back({{"id", e.id}, {"weight", e.weight}, {"column", e.column}, {"visibility", e.visibility}});
    return {{"id_column", r.idColumn},
            {"total_column", r.totalColumn},
            {"credit",
             {{"probe_weight", r.probeWeight},
              {"image_weight", r.imageWeight},
              {"failed_scene_max", r.failedSceneMax},
              {"zero_credit_mean_lsb", r.zeroCreditMeanLsb},
              {"fail_max", r.failMax}}},
            {"gradescope",
             {{"output_format", r.gradescope.outputFormat},
              {"visibility", r.gradescope.visibility},
              {"stdout_visibility", r.gradescope.stdoutVisibility},
              {"leaderboard", r.gradescope.leaderboard}}},
            {"exercises", exercises}};
}

long exerciseHundredths(const Rubric& r, const RubricExercise& e, const ExerciseGrade* grade) {
    if (!grade || grade->refused) return 0;
    const ExerciseReport& report = grade->report;
    if (report.status == CheckStatus::Pass) return toHundredths(e.weight);
    if (report.status != CheckStatus::Fail) return 0;
    double imageScore = 0;
    for (const ImageSummary& image : report.images) {
        if (image.passed)
            imageScore += 1;
        else if (image.nonFinite == 0)
            imageScore += r.failedSceneMax * std::max(0.0, 1.0 - image.meanLsb / r.zeroCreditMeanLsb);
    }
    if (!report.images.empty()) imageScore /= double(report.images.size());
    double credit = report.probes.empty() ? imageScore
                                          : r.probeWeight * report.probeFraction() + r.imageWeight * imageScore;
    // A FAIL never rounds up to full marks, whatever fail_max says.
    long full = toHundredths(e.weight);
    return std::max(0L, std::min(toHundredths(e.weight * std::clamp(credit, 0.0, r.failMax)), full - 1));
}

StudentScore scoreStudent(const Rubric& r, const StudentGrade& g) {
    StudentScore s;
    for (const RubricExercise& e : r.exercises) {
        s.hundredths.push_back(exerciseHundredths(r, e, g.find(e.id)));
        s.total += s.hundredths.back();
    }
    return s;
}

std::string formatPoints(long hundredths) {
    char b[32];
    std::snprintf(b, sizeof b, "%s%ld.%02ld", hundredths < 0 ? "-" : "", std::labs(hundredths) / 100,
                  std::labs(hundredths) % 100);
    return b;
}

}  // namespace rl

// How checker reports become points: each exercise's weight, and how
// partial credit follows from the probes and the check images. The format
// and the default are documented in docs/grading.md; the default rubric is
// grading/default-rubric.json at the raylab root.
//
//   PASS                                          -> weight
//   NOT STARTED, COMPILE ERROR, TIMEOUT, CRASH, REFUSED -> 0
//   FAIL -> weight * min(fail_max, probe_weight * probeFraction + image_weight * imageScore)
//   imageScore = mean over check scenes of
//       1                                          the scene within budget
//       0                                          NaN or Inf in the render
//       failed_scene_max * max(0, 1 - meanLsb / zero_credit_mean_lsb)   otherwise
// An exercise without probes counts its images only. Points are rounded to
// hundredths per exercise, and the total is the sum of the rounded points,
// so the CSV adds up exactly.
#pragma once

#include "grading/student_grade.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace rl {

struct RubricExercise {
    std::string id;      // "05-ggx"
    double weight = 0;   // points for a PASS
    std::string column;  // its grades.csv header (default: the id)
    std::string visibility = "visible";  // Gradescope: visible, after_due_date, after_published or hidden
};

// How results.json is written for Gradescope (the rubric's "gradescope" object).
struct GradescopeSettings {
    std::string outputFormat = "text";      // text, md, html, simple_format or ansi: how Gradescope renders outputs
    std::string visibility = "visible";     // of the whole result
    std::string stdoutVisibility = "hidden";  // of the autograder's log
    bool leaderboard = false;               // a leaderboard entry with the total
};

struct Rubric {
    std::string idColumn = "Student";  // grades.csv header of the id column ("Username" for Moodle)
    std::string totalColumn = "Total";
    double probeWeight = 0.5;          // share of a FAIL's credit from the probe pass fraction
    double imageWeight = 0.5;          // share from the check images (probe + image = 1)
    double failedSceneMax = 0.5;       // most credit for a check scene over budget
    double zeroCreditMeanLsb = 8;      // mean error (in 1/255) at which a failed scene earns nothing
    double failMax = 0.75;             // most credit for a FAIL: a mistake in a rare case is still a mistake
    std::vector<RubricExercise> exercises;  // graded and listed in this order; others are not checked
    GradescopeSettings gradescope;

    long maxHundredths() const;
};

// The default: <raylab root>/grading/default-rubric.json.
std::filesystem::path defaultRubricPath();

// Reads and validates a rubric; throws rl::Error "file: what is wrong".
Rubric loadRubric(const std::filesystem::path& file);
Rubric rubricFromJson(const nlohmann::json& j, const std::string& shownName);
nlohmann::json toJson(const Rubric& rubric);

// Points of one exercise (nullptr: not graded at all) in hundredths.
long exerciseHundredths(const Rubric& rubric, const RubricExercise& exercise, const ExerciseGrade* grade);

struct StudentScore {
    std::vector<long> hundredths;  // per rubric exercise
    long total = 0;
};
StudentScore scoreStudent(const Rubric& rubric, const StudentGrade& grade);

// Fixed formatting: "12.50".
std::string formatPoints(long hundredths);

}  // namespace rl

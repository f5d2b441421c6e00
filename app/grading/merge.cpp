#include "grading/merge.h"

#include "core/error.h"
#include "core/json_text.h"
#include "grading/atomic_file.h"
#include "grading/class_similarity.h"
#include "grading/student_list.h"
#include "grading/outputs.h"
#include "grading/rubric.h"
#include "grading/student_grade.h"
#include "grading/summary.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <map>
#include <set>

namespace fs = std::filesystem;

namespace rl {

using nlohmann::json;

namespace {

json readJson(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw Error(path.string() + ": missing (is this the output of `raylab grade`, and did it finish?)");
    return parseJsonText(readWholeFile(path), path.string());
}

}  // namespace

void mergeGradeOutputs(const std::vector<fs::path>& shards, const fs::path& out, std::ostream& log) {
    auto start = std::chrono::steady_clock::now();
    if (shards.empty()) throw Error("merge: name the output folders of the shards to join");
    std::error_code ec;
    for (const fs::path& shard : shards)
        if (pathsOverlap(shard, out))
            throw Error(out.string() + ": the merged output must be a folder of its own, apart from " + shard.string());

    json rubricJson;
    Rubric rubric;
    int shardCount = 0;
    std::size_t submissionsTotal = 0;
    std::map<int, fs::path> seenShards;
    std::map<std::string, fs::path> owner;  // student id -> shard folder
    std::vector<StudentGrade> grades;
    json ignoredPart;  // every shard lists the same SUBMISSIONS: the first one's
    RunInfo info;
    for (const fs::path& shard : shards) {
        json r = readJson(shard / "rubric.json");
        json s = readJson(shard / "summary.json");
        if (rubricJson.is_null()) {
            rubricJson = r;
            rubric = rubricFromJson(r, (shard / "rubric.json").string());
        } else if (r != rubricJson) {
            throw Error((shard / "rubric.json").string() + ": differs from " + (shards[0] / "rubric.json").string() +
                        ": shards must be graded with the same rubric");
        }
        int index = s.at("shard").value("index", 1), count = s.at("shard").value("count", 1);
        if (shardCount == 0) shardCount = count;
        if (count != shardCount)
            throw Error(shard.string() + ": shard " + std::to_string(index) + "/" + std::to_string(count) +
                        " does not belong with shards of " + std::to_string(shardCount));
        if (seenShards.count(index))
            throw Error(shard.string() + ": shard " + std::to_string(index) + "/" + std::to_string(count) +
                        " is also " + seenShards[index].string());
        seenShards[index] = shard;
        submissionsTotal = std::max<std::size_t>(submissionsTotal, s.value("submissions_total", 0));
        if (ignoredPart.is_null())
            ignoredPart = {{"ignored_count", s.value("ignored_count", 0)},
                           {"ignored_by_reason", s.value("ignored_by_reason", json::array())},
                           {"ignored_entries", s.value("ignored_entries", json::array())}};
        info.graded += s.value("graded_this_run", 0);
        info.skipped += s.value("skipped_already_graded", 0);
        info.jobs = s.value("jobs", 1);
        info.timeoutSeconds = s.value("timeout_seconds", 0.0);
        for (const std::string& id : readStudentList(shard)) {
            if (owner.count(id))
                throw Error(shard.string() + ": student " + id + " was also graded in " + owner[id].string());
            owner[id] = shard;
            std::optional<StudentGrade> g = loadStudentGrade(shard, id);
            if (!g) throw Error(gradeRecordPath(shard, id).string() + ": missing or unreadable");
            grades.push_back(*g);
        }
    }
    std::string missing;
    for (int k = 1; k <= shardCount; ++k)
        if (!seenShards.count(k)) missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(shardCount);
    if (!missing.empty()) throw Error("merge: shard " + missing + " is missing");
    if (grades.size() != submissionsTotal)
        throw Error("merge: the shards hold " + std::to_string(grades.size()) + " students, but SUBMISSIONS held " +
                    std::to_string(submissionsTotal));

    fs::create_directories(out, ec);
    if (ec) throw Error(out.string() + ": cannot create (" + ec.message() + ")");
    FolderLock lock(out);
    for (const auto& [id, shard] : owner) {
        // Copied beside the old folder, which is replaced only once the copy is whole.
        fs::path target = studentDir(out, id);
        fs::path staged = target;
        staged += ".merging";
        fs::remove_all(staged, ec);
        fs::copy(studentDir(shard, id), staged, fs::copy_options::recursive, ec);
        if (ec) {
            fs::remove_all(staged, ec);
            throw Error(target.string() + ": cannot copy from " + shard.string() + " (" + ec.message() + ")");
        }
        fs::remove_all(target, ec);
        fs::rename(staged, target, ec);
        if (ec) throw Error(target.string() + ": cannot replace (" + ec.message() + ")");
    }
    for (const fs::path& shard : shards)
        for (fs::directory_iterator it(shard / "_reference", ec), end; !ec && it != end; it.increment(ec))
            writeOutputFile(out / "_reference" / it->path().filename(),
                            readRegularFile(it->path(), kMaxImageFileBytes, "the reference image"));

    std::sort(grades.begin(), grades.end(), [](const StudentGrade& a, const StudentGrade& b) { return a.id < b.id; });
    info.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    info.submissionsTotal = submissionsTotal;
    json summary = gradeSummary(rubric, grades, info);
    for (const auto& [key, value] : ignoredPart.items()) summary[key] = value;
    // Compared across the whole class, as an unsharded run does.
    summary["similar_submissions"] = classSimilarity(out, rubric, grades);
    for (const std::string& failed : writeClassOutputs(out, rubric, grades, summary))
        log << "raylab: " << failed << " (the class goes on without this student's files)\n";
    log << "merged " << shards.size() << " shard" << (shards.size() == 1 ? "" : "s") << ", " << grades.size()
        << " students, into " << (out / "grades.csv").string() << "\n";
}

}  // namespace rl

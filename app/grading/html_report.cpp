#include "grading/html_report.h"

#include "core/message.h"
#include "course/exercise_registry.h"
#include "grading/summary.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <regex>

namespace rl {

using nlohmann::json;

namespace {

const char* kStyle = R"(<style>
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",sans-serif;margin:24px;color:#1d1d1f;background:#fff}
h1{font-size:22px;margin:0 0 8px} h2{font-size:17px;margin:28px 0 6px;border-bottom:1px solid #ddd;padding-bottom:4px}
table{border-collapse:collapse;margin:8px 0} th,td{border:1px solid #d0d0d0;padding:4px 8px;text-align:right;vertical-align:top}
th{background:#f2f2f2;font-weight:600} td{white-space:nowrap} td.l,th.l{text-align:left}
td.wrap{white-space:normal;min-width:16em}
table.sortable th{cursor:pointer;user-select:none} table.sortable th:hover{background:#e4e4e4}
th[aria-sort=ascending]::after{content:" \25B2"} th[aria-sort=descending]::after{content:" \25BC"}
.s-pass{background:#dff3df} .s-fail{background:#ffe9c2} .s-error{background:#f9d0d0;color:#7a0000} .s-none{background:#eee;color:#666}
tr.problem td.id{border-left:4px solid #d33}
.badge{display:inline-block;padding:1px 8px;border-radius:9px;font-size:12px;font-weight:600;vertical-align:middle}
.notes{background:#fff6d8;border:1px solid #e8d48a;padding:6px 12px;margin:8px 0}
.muted{color:#666} pre{background:#f7f7f7;border:1px solid #ddd;padding:8px;overflow-x:auto;font-size:12px}
.scenes{display:flex;flex-wrap:wrap;gap:14px} figure{margin:0;border:1px solid #ddd;padding:6px}
figure .row{display:flex;gap:6px} figure .img{text-align:center;font-size:11px;color:#555}
figure img{height:108px;image-rendering:pixelated;display:block;background:#888}
figcaption{font-size:12px;margin-top:4px}
#grades{width:100%;font-size:13px} #grades th,#grades td{padding:3px 5px} #grades td.x{white-space:normal;width:5.4em}
.why{display:block;font-size:11px;line-height:1.15;color:#444;text-align:left;white-space:normal;overflow-wrap:anywhere;max-width:5.8em}
#grades td.notecol{white-space:normal;min-width:11em;font-size:12px;overflow-wrap:anywhere}
#grades td.id{white-space:normal;overflow-wrap:anywhere;max-width:14em}
details.similar td,details.reason li{white-space:normal;overflow-wrap:anywhere} details.similar>summary,details.reason>summary{cursor:pointer;overflow-wrap:anywhere}
a.more{font-size:11px;white-space:nowrap}
.filter{margin:8px 0;display:flex;gap:12px;align-items:center} .filter input[type=search]{width:22em;font:inherit;padding:3px 6px}
details.passed{margin:16px 0} details.passed>summary{cursor:pointer;font-weight:600}
</style>
)";

// Sorts the table whose header was clicked: numbers by data-v, text otherwise.
const char* kSortScript = R"(<script>
document.querySelectorAll('table.sortable th').forEach(function (th, col) {
  th.addEventListener('click', function () {
    var table = th.closest('table'), body = table.tBodies[0];
    var ascending = th.getAttribute('aria-sort') !== 'ascending';
    table.querySelectorAll('th').forEach(function (h) { h.removeAttribute('aria-sort'); });
    th.setAttribute('aria-sort', ascending ? 'ascending' : 'descending');
    var numeric = th.dataset.type === 'num';
    var key = function (row) { var c = row.cells[col]; return c.dataset.v !== undefined ? c.dataset.v : c.textContent; };
    var rows = Array.prototype.slice.call(body.rows);
    rows.sort(function (a, b) {
      var x = key(a), y = key(b);
      var d = numeric ? parseFloat(x) - parseFloat(y) : x.localeCompare(y);
      return ascending ? d : -d;
    });
    rows.forEach(function (r) { body.appendChild(r); });
  });
});
</script>
)";

// The filter box: keeps the rows whose text or reasons hold every word typed,
// and, when ticked, only students with a problem.
const char* kFilterScript = R"(<script>
(function () {
  var box = document.getElementById('filter'), only = document.getElementById('problems-only');
  function apply() {
    var words = box.value.toLowerCase().split(/\s+/).filter(Boolean), shown = 0;
    document.querySelectorAll('#grades tbody tr').forEach(function (row) {
      var text = (row.textContent + ' ' + Array.prototype.map.call(row.querySelectorAll('[title]'),
                  function (c) { return c.title; }).join(' ')).toLowerCase();
      var ok = words.every(function (w) { return text.indexOf(w) >= 0; }) &&
               (!only.checked || row.classList.contains('problem'));
      row.hidden = !ok;
      shown += ok;
    });
    document.getElementById('shown').textContent = shown + ' shown';
  }
  box.addEventListener('input', apply);
  only.addEventListener('change', apply);
  apply();
})();
</script>
)";

// The reason in a few words, for the class table's cell (the tooltip has it all).
std::string shortReason(const ExerciseGrade* g) {
    if (!g) return "not started";
    const ExerciseReport& r = g->report;
    std::string status = gradeStatus(*g);
    if (status == "PASS") return "";
    if (status == "FAIL") {
        int passed = 0, total = 0;
        for (const ProbeSummary& p : r.probes) {
            passed += p.passed;
            total += p.total;
        }
        int images = 0;
        for (const ImageSummary& i : r.images) images += i.passed;
        std::string why = total ? "probes " + std::to_string(passed) + "/" + std::to_string(total) : "";
        if (!r.images.empty())
            why += (why.empty() ? "" : ", ") + std::string("img ") + std::to_string(images) + "/" + std::to_string(r.images.size());
        return why;
    }
    if (status == "COMPILE ERROR") {
        static const std::regex fileLine(R"(^([^:\s]+:\d+))");  // "05-ggx.glsl:3: error: ..."
        std::smatch m;
        return std::regex_search(r.message, m, fileLine) ? m[1].str() : std::string("compile error");
    }
    if (status == "NOT STARTED") return r.message.find("missing") != std::string::npos ? "missing" : "not started";
    if (status == "TIMEOUT") return "timeout";
    if (status == "CRASH") return "crash";
    return "refused";
}

std::string statusClass(const ExerciseGrade* g) {
    if (!g) return "s-none";
    std::string s = gradeStatus(*g);
    if (s == "PASS") return "s-pass";
    if (s == "FAIL") return "s-fail";
    if (s == "NOT STARTED") return "s-none";
    return "s-error";
}

std::string fixed(double x, int decimals) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", decimals, x);
    return b;
}

// Lets a long column name ("08-cook-torrance") wrap after its hyphens.
std::string breakable(const std::string& html) {
    std::string out;
    for (char c : html) out += c == '-' ? std::string("-<wbr>") : std::string(1, c);
    return out;
}

// At most `chars` characters of UTF-8 text: the first chars - 2 and an ellipsis.
std::string shortened(const std::string& text, std::size_t chars) {
    std::size_t count = 0, cut = std::string::npos;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if ((static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) continue;
        if (count == chars - 2) cut = i;
        ++count;
    }
    return count <= chars ? text : text.substr(0, cut) + "\xE2\x80\xA6";
}

// A cluster's pairs: "a and b share 41 fingerprints (100%) in 08-cook-torrance; ...".
std::string pairsText(const json& pairs) {
    std::string out;
    for (const json& p : pairs) {
        char share[16];
        std::snprintf(share, sizeof share, "%.0f%%", 100.0 * p.value("similarity", 0.0));
        out += (out.empty() ? "Pairs: " : "; ") + htmlEscape(p.value("a", "")) + " and " + htmlEscape(p.value("b", "")) +
               " share " + std::to_string(p.value("evidence", 0)) + " fingerprints (" + share + ") in " +
               htmlEscape(p.value("exercise", ""));
    }
    return out.empty() ? "" : out + ".</p><p>";
}

std::string pageHead(const std::string& title) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + htmlEscape(title) +
           "</title>\n" + kStyle + "</head>\n<body>\n";
}

// An image path stored relative to the student's folder, as a URL.
std::string imageUrl(const std::string& path) {
    std::string url, segment;
    for (char c : path) {
        if (c == '/') {
            url += (segment == ".." ? segment : urlSegment(segment)) + "/";
            segment.clear();
        } else {
            segment += c;
        }
    }
    return url + urlSegment(segment);
}

}  // namespace

std::string htmlEscape(const std::string& raw) {
    // Control characters, bidirectional controls and bytes that are not UTF-8
    // shown as escapes (\x1b, \u202e, \xe9), as on the terminal; tabs and newlines kept.
    std::string text;
    std::size_t from = 0;
    for (;;) {
        const std::size_t tab = raw.find('\t', from);
        text += printableLines(std::string_view(raw).substr(from, tab == std::string::npos ? std::string::npos : tab - from),
                               std::string::npos);
        if (tab == std::string::npos) break;
        text += '\t';
        from = tab + 1;
    }
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string urlSegment(const std::string& text) {
    std::string out;
    for (unsigned char c : text) {
        if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
            out += char(c);
        } else {
            char b[4];
            std::snprintf(b, sizeof b, "%%%02X", c);
            out += b;
        }
    }
    return out;
}

std::string classIndexPage(const Rubric& rubric, const std::vector<StudentGrade>& grades, const json& summary) {
    std::string max = formatPoints(rubric.maxHundredths());
    std::string html = pageHead("raylab grades");
    html += "<h1>raylab grades</h1>\n<p>";
    html += std::to_string(grades.size()) + " students &middot; mean " +
            fixed(summary.value("mean_total", 0.0), 2) + " / " + max + " &middot; " +
            std::to_string(summary.value("full_marks", 0)) + " at full marks &middot; exercises: ";
    bool first = true;
    const json outcomes = summary.value("exercise_outcomes", json::object());
    for (const auto& [status, count] : outcomes.items()) {
        html += (first ? "" : ", ") + htmlEscape(status) + " " + std::to_string(count.get<int>());
        first = false;
    }
    html += "</p>\n<p class=\"muted\">Click a column header to sort. Each cell gives the points and, under them, "
            "the reason in short (probe cases and check images passed, the file and line of a compile error, ...); "
            "its tooltip gives the whole reason, and the student's page the renders, differences and logs. "
            "Files: <a href=\"grades.csv\">grades.csv</a>, <a href=\"summary.json\">summary.json</a>, "
            "<a href=\"rubric.json\">rubric.json</a>.</p>\n";
    // What was not graded, first: an instructor must see a dropped student here, not on a terminal long closed.
    // Grouped by reason with counts; the names of each reason one click away.
    const json ignored = summary.value("ignored_entries", json::array());
    const json missing = summary.value("roster_without_submission", json::array());
    const json unmatched = summary.value("submissions_without_roster_student", json::array());
    const json unwritten = summary.value("students_not_written", json::array());
    const std::string testStudent = summary.value("roster_test_student", "");
    const std::size_t ignoredCount = summary.value("ignored_count", ignored.size());
    std::vector<std::string> failedIds;
    for (const StudentGrade& g : grades)
        if (!g.complete) failedIds.push_back(g.id);
    auto names = [](const json& list, std::size_t total) {
        std::string out = "<ul>";
        for (const json& i : list) out += "<li>" + htmlEscape(i.is_string() ? i.get<std::string>() : i.dump()) + "</li>";
        if (total > list.size()) out += "<li class=\"muted\">and " + std::to_string(total - list.size()) + " more (summary.json has the counts)</li>";
        return out + "</ul>";
    };
    auto reasonLine = [](std::size_t n, const std::string& what, const std::string& list) {
        return "<details class=\"reason\"><summary><b>" + std::to_string(n) + "</b> " + what + "</summary>" + list +
               "</details>\n";
    };
    std::string box;
    if (!failedIds.empty()) {
        json ids = json::array();
        for (const std::string& id : failedIds) ids.push_back(id);
        box += reasonLine(failedIds.size(), "student" + std::string(failedIds.size() == 1 ? "" : "s") +
                                                " the grader itself failed for (graded again by the next run)",
                          names(ids, ids.size()));
    }
    if (!unwritten.empty())
        box += reasonLine(unwritten.size(), "student folder" + std::string(unwritten.size() == 1 ? "" : "s") +
                                                " that could not be written (the grades are in grades.csv)",
                          names(unwritten, unwritten.size()));
    if (ignoredCount) {
        // Each reason of the submissions folder's entries that are no student, with its count.
        std::map<std::string, json> byWhy;
        for (const json& i : ignored)
            if (i.is_string()) byWhy[reasonOf(i.get<std::string>())].push_back(i.get<std::string>());
        for (const json& r : summary.value("ignored_by_reason", json::array())) {
            const std::string why = r.value("reason", "other");
            const std::size_t n = r.value("count", std::size_t(0));
            box += reasonLine(n, "entr" + std::string(n == 1 ? "y" : "ies") + " of the submissions folder not graded: " +
                                     htmlEscape(why),
                              names(byWhy.count(why) ? byWhy[why] : json::array(), n));
        }
    }
    if (!missing.empty())
        box += reasonLine(summary.value("roster_without_submission_count", missing.size()),
                          "student" + std::string(missing.size() == 1 ? "" : "s") + " of the roster without a submission",
                          names(missing, summary.value("roster_without_submission_count", missing.size())));
    if (!unmatched.empty())
        box += reasonLine(summary.value("submissions_without_roster_student_count", unmatched.size()),
                          "graded submission" + std::string(unmatched.size() == 1 ? "" : "s") +
                              " that no roster student matches (left out of the gradebook export)",
                          names(unmatched, summary.value("submissions_without_roster_student_count", unmatched.size())));
    if (!testStudent.empty()) box += "<p class=\"muted\" id=\"test-student\">" + htmlEscape(testStudent) + "</p>\n";
    if (!box.empty()) html += "<div class=\"notes\" id=\"not-graded\"><b>Not graded</b>\n" + box + "</div>\n";
    html += "<div class=\"filter\"><input type=\"search\" id=\"filter\" placeholder=\"Filter: id, status, reason, "
            "note...\" aria-label=\"Filter the students\"><label><input type=\"checkbox\" id=\"problems-only\"> only "
            "students with problems (a lost point or an entry not graded)</label><span class=\"muted\" id=\"shown\"></span></div>\n";
    html += "<table class=\"sortable\" id=\"grades\">\n<thead><tr><th class=\"l\" data-type=\"text\">" +
            htmlEscape(rubric.idColumn) + "</th>";
    for (const RubricExercise& e : rubric.exercises)
        html += "<th data-type=\"num\">" + breakable(htmlEscape(e.column)) + "<br><span class=\"muted\">/&nbsp;" +
                formatPoints(std::lround(e.weight * 100)) + "</span></th>";
    html += "<th data-type=\"num\">" + htmlEscape(rubric.totalColumn) + "<br><span class=\"muted\">/&nbsp;" + max +
            "</span></th><th data-type=\"num\">Prob&shy;lems</th><th class=\"l\" data-type=\"text\">Notes</th></tr></thead>\n<tbody>\n";
    for (const StudentGrade& g : grades) {
        StudentScore s = scoreStudent(rubric, g);
        // A problem is a lost point, or an exercise the grader could not grade (it failed, or
        // the file was refused): a missing optional exercise at full marks is none.
        int problems = 0;
        std::string cells;
        for (std::size_t k = 0; k < rubric.exercises.size(); ++k) {
            const ExerciseGrade* x = g.find(rubric.exercises[k].id);
            std::string status = x ? gradeStatus(*x) : "NOT STARTED";
            problems += s.hundredths[k] < std::lround(rubric.exercises[k].weight * 100) || status == "REFUSED" ||
                        status == "CRASH" || !g.complete;
            std::string tip = status + (x && !x->report.message.empty() ? ": " + x->report.message : "");
            std::string why = shortReason(x);
            cells += "<td class=\"x " + statusClass(x) + "\" data-v=\"" + formatPoints(s.hundredths[k]) + "\" title=\"" +
                     htmlEscape(tip) + "\">" + formatPoints(s.hundredths[k]) +
                     (why.empty() ? "" : "<span class=\"why\">" + htmlEscape(why) + "</span>") + "</td>";
        }
        // The first note, short; the rest on the student's page, one click away.
        std::string notes;
        if (!g.notes.empty()) {
            std::string first = g.notes[0];
            if (first.size() > 70) {
                std::size_t cut = 64;
                while (cut > 0 && (static_cast<unsigned char>(first[cut]) & 0xC0) == 0x80) --cut;
                first = first.substr(0, cut) + "...";
            }
            notes = htmlEscape(first);
            if (g.notes.size() > 1 || first != g.notes[0])
                notes += " <a class=\"more\" href=\"" + urlSegment(g.id) + "/index.html#notes\">" +
                         (g.notes.size() > 1 ? "+" + std::to_string(g.notes.size() - 1) + " more" : "more") + "</a>";
        }
        // A long id (up to 100 bytes) in a few characters, whole in its tooltip: rows stay a line or two.
        const std::string shown = shortened(g.id, 24);
        html += std::string("<tr") + (problems ? " class=\"problem\"" : "") + "><td class=\"l id\"" +
                (shown == g.id ? "" : " title=\"" + htmlEscape(g.id) + "\"") + "><a href=\"" + urlSegment(g.id) +
                "/index.html\">" + htmlEscape(shown) + "</a></td>" + cells + "<td data-v=\"" +
                formatPoints(s.total) + "\"><b>" + formatPoints(s.total) + "</b></td><td data-v=\"" +
                std::to_string(problems) + "\"" + (problems ? " class=\"s-fail\"" : "") + ">" +
                std::to_string(problems) + "</td><td class=\"l notecol\">" + notes + "</td></tr>\n";
    }
    html += "</tbody>\n</table>\n";
    // What the class got wrong: the page to open before the next lecture.
    const json mistakes = summary.value("class_mistakes", json::array());
    std::string rows;
    for (const json& m : mistakes) {
        std::string list;
        for (const json& h : m.value("hints", json::array()))
            list += "<li>" + std::to_string(h.value("students", 0)) + " &times; " + htmlEscape(h.value("hint", "")) + "</li>";
        std::string probes;
        for (const json& p : m.value("failed_probe_groups", json::array()))
            probes += (probes.empty() ? "" : ", ") + htmlEscape(p.value("probe_group", "")) + " (" +
                      std::to_string(p.value("students", 0)) + ")";
        std::string statuses;
        for (const json& st : m.value("not_passed", json::array()))
            statuses += (statuses.empty() ? "" : ", ") + htmlEscape(st.value("status", "")) + " " +
                        std::to_string(st.value("students", 0));
        if (statuses.empty()) continue;
        rows += "<tr><td class=\"l\">" + htmlEscape(m.value("exercise", "")) + "</td><td>" +
                std::to_string(m.value("passed", 0)) + "</td><td class=\"l wrap\">" + statuses +
                "</td><td class=\"l wrap\">" + (list.empty() ? "" : "<ul>" + list + "</ul>") +
                "</td><td class=\"l wrap\">" + probes + "</td></tr>\n";
    }
    if (!rows.empty())
        html += "<h2 id=\"mistakes\">What the class got wrong</h2>\n<table id=\"class-mistakes\">\n<thead><tr><th "
                "class=\"l\">Exercise</th><th>Passed</th><th class=\"l\">Not passed</th><th class=\"l\">Mistakes the "
                "checker recognised (students &times; hint)</th><th class=\"l\">Probe groups failed (students)</th>"
                "</tr></thead>\n<tbody>\n" + rows + "</tbody>\n</table>\n";
    // Similar submissions, as clusters: for the instructor to look at; grades are not changed by them.
    const json similarity = summary.value("similar_submissions", json::object());
    const json clusters = similarity.is_object() ? similarity.value("clusters", json::array()) : json::array();
    if (!clusters.empty()) {
        const std::size_t found = similarity.value("clusters_found", clusters.size());
        html += "<h2 id=\"similar\">Similar submissions</h2>\n<p class=\"muted\">" + std::to_string(found) +
                " cluster" + (found == 1 ? "" : "s") + " of students whose files share code outside base code" +
                (found > clusters.size() ? " (the " + std::to_string(clusters.size()) + " with the most evidence listed)" : "") +
                ", the most evidence first. Base code is never evidence: the stub's and the solution's code, and "
                "code more than 20% of the class share. Identifiers are normalised (renaming is seen through) and "
                "functions compared in any order. Information only: no grade changes.</p>\n";
        for (const json& c : clusters) {
            const json ex = c.value("example", json::object());
            const std::string a = ex.value("a", ""), b = ex.value("b", "");
            std::string who;
            for (const json& id : c.value("students", json::array())) {
                const std::string sid = id.get<std::string>();
                who += (who.empty() ? "" : ", ") + ("<a href=\"" + urlSegment(sid) + "/index.html\">" + htmlEscape(sid) + "</a>");
            }
            const std::size_t count = c.value("student_count", std::size_t(0));
            if (count > c.value("students", json::array()).size()) who += " and " + std::to_string(count - c["students"].size()) + " more";
            std::string exercises;
            for (const json& e : c.value("exercises", json::array())) exercises += (exercises.empty() ? "" : ", ") + htmlEscape(e.get<std::string>());
            char share[16];
            std::snprintf(share, sizeof share, "%.0f%%", 100.0 * c.value("similarity", 0.0));
            html += "<details class=\"similar\"><summary>" + std::to_string(count) + " students, " +
                    htmlEscape(c.value("kind", "")) + " in " + exercises + " &middot; evidence " +
                    std::to_string(c.value("evidence", 0)) + " (" + share + "): " + who + "</summary>\n<p>" +
                    pairsText(c.value("pairs", json::array())) +
                    htmlEscape(ex.value("exercise", "")) + ", " + htmlEscape(a) + " beside " + htmlEscape(b) +
                    ":</p><table><thead><tr><th>" + htmlEscape(a) + " line</th><th>" + htmlEscape(b) +
                    " line</th><th class=\"l\">Line of " + htmlEscape(a) + "</th></tr></thead><tbody>\n";
            for (const json& l : ex.value("shared_lines", json::array()))
                html += "<tr><td>" + std::to_string(l.value("line_a", 0)) + "</td><td>" + std::to_string(l.value("line_b", 0)) +
                        "</td><td class=\"l\"><code>" + htmlEscape(l.value("text", "")) + "</code></td></tr>\n";
            html += "</tbody></table></details>\n";
        }
    }
    html += kSortScript;
    html += kFilterScript;
    html += "</body>\n</html>\n";
    return html;
}

std::string studentPage(const Rubric& rubric, const StudentGrade& g) {
    StudentScore s = scoreStudent(rubric, g);
    std::string html = pageHead(g.id + " - raylab grade");
    html += "<p><a href=\"../index.html\">&larr; all students</a></p>\n";
    html += "<h1>" + htmlEscape(g.id) + ": " + formatPoints(s.total) + " / " + formatPoints(rubric.maxHundredths()) +
            "</h1>\n<p class=\"muted\">Submitted as " + htmlEscape(g.source) + "; graded in " + fixed(g.seconds, 1) +
            " s. The files graded are in <a href=\"submission/\">submission/</a>.</p>\n";
    if (!g.notes.empty()) {
        html += "<div class=\"notes\" id=\"notes\"><b>About the submission</b><ul>\n";
        for (const std::string& n : g.notes) html += "<li>" + htmlEscape(n) + "</li>\n";
        html += "</ul></div>\n";
    }
    html += "<table>\n<thead><tr><th class=\"l\">Exercise</th><th class=\"l\">Status</th><th>Points</th><th "
            "class=\"l\">Reason</th></tr></thead>\n<tbody>\n";
    for (std::size_t k = 0; k < rubric.exercises.size(); ++k) {
        const RubricExercise& e = rubric.exercises[k];
        const ExerciseGrade* x = g.find(e.id);
        html += "<tr><td class=\"l\"><a href=\"#" + urlSegment(e.id) + "\">" + htmlEscape(e.id) + "</a></td><td class=\"l " +
                statusClass(x) + "\">" + htmlEscape(x ? gradeStatus(*x) : "NOT STARTED") + "</td><td>" +
                formatPoints(s.hundredths[k]) + " / " + formatPoints(std::lround(e.weight * 100)) +
                "</td><td class=\"l wrap\">" + htmlEscape(x ? x->report.message : "") + "</td></tr>\n";
    }
    html += "</tbody>\n</table>\n";

    // One exercise's section: what failed first, passing check scenes folded away.
    auto figure = [](const ImageSummary& i) {
        std::string f = "<figure><div class=\"row\">";
        for (const auto& [label, path] : {std::pair<const char*, const std::string&>{"yours", i.gotPng},
                                          {"reference", i.expectedPng},
                                          {"difference", i.diffPng}}) {
            f += "<div class=\"img\">";
            if (!path.empty())
                f += "<img src=\"" + htmlEscape(imageUrl(path)) + "\" alt=\"" + htmlEscape(i.scene) + " " + label + "\">";
            f += std::string(label) + "</div>";
        }
        return f + "</div><figcaption><b class=\"badge " + std::string(i.passed ? "s-pass" : "s-fail") + "\">" +
               (i.passed ? "PASS" : "FAIL") + "</b> " + htmlEscape(i.scene) + ": " + fixed(100 * i.offFraction, 2) +
               "% of pixels off, mean " + fixed(i.meanLsb, 2) + "/255" +
               (i.nonFinite ? ", " + std::to_string(i.nonFinite) + " NaN/Inf" : "") + "</figcaption></figure>\n";
    };
    auto section = [&](std::size_t k) {
        const RubricExercise& e = rubric.exercises[k];
        const ExerciseGrade* x = g.find(e.id);
        const ExerciseInfo& info = findExercise(e.id);
        std::string out = "<h2 id=\"" + htmlEscape(urlSegment(e.id)) + "\">" + htmlEscape(e.id + ": " + info.title) +
                          " <span class=\"badge " + statusClass(x) + "\">" +
                          htmlEscape(x ? gradeStatus(*x) : "NOT STARTED") + "</span> " + formatPoints(s.hundredths[k]) +
                          " / " + formatPoints(std::lround(e.weight * 100)) + "</h2>\n";
        if (!x) return out;
        const ExerciseReport& r = x->report;
        if (!r.message.empty()) out += "<p>" + htmlEscape(r.message) + "</p>\n";
        if (!r.hint.empty()) out += "<p class=\"muted\">hint: " + htmlEscape(r.hint) + "</p>\n";
        if (!r.details.empty() && r.status != CheckStatus::Pass)
            out += std::string("<details open><summary>") +
                   (r.status == CheckStatus::CompileError ? "Compile log" : "Details") + "</summary><pre>" +
                   htmlEscape(r.details) + "</pre></details>\n";
        if (!r.probes.empty()) {
            out += "<table><thead><tr><th class=\"l\">Probe</th><th>Cases passed</th></tr></thead><tbody>\n";
            for (const ProbeSummary& p : r.probes)
                out += "<tr><td class=\"l\">" + htmlEscape(p.name) + "</td><td class=\"" +
                       (p.passed == p.total ? "s-pass" : "s-fail") + "\">" + std::to_string(p.passed) + " / " +
                       std::to_string(p.total) + "</td></tr>\n";
            out += "</tbody></table>\n";
        }
        std::string failing, passing;
        int passed = 0;
        for (const ImageSummary& i : r.images) {
            (i.passed ? passing : failing) += figure(i);
            passed += i.passed;
        }
        if (!failing.empty()) out += "<div class=\"scenes\">\n" + failing + "</div>\n";
        if (!passing.empty())
            out += std::string("<details") + (failing.empty() && r.status != CheckStatus::Pass ? " open" : "") +
                   "><summary>" + std::to_string(passed) + " check scene" + (passed == 1 ? "" : "s") +
                   " within budget</summary><div class=\"scenes\">\n" + passing + "</div></details>\n";
        if (!r.details.empty() && r.status == CheckStatus::Pass)
            out += "<details><summary>Details</summary><pre>" + htmlEscape(r.details) + "</pre></details>\n";
        return out;
    };
    // Failures first, in rubric order; the passes folded into one summary at the end.
    std::string passes, passNames;
    int passCount = 0;
    for (std::size_t k = 0; k < rubric.exercises.size(); ++k) {
        const ExerciseGrade* x = g.find(rubric.exercises[k].id);
        if (x && gradeStatus(*x) == "PASS") {
            passes += section(k);
            passNames += (passCount++ ? ", " : "") + rubric.exercises[k].id;
        } else {
            html += section(k);
        }
    }
    if (passCount)
        html += "<details class=\"passed\"><summary>" + std::to_string(passCount) + " exercise" +
                (passCount == 1 ? "" : "s") + " passed: " + htmlEscape(passNames) + "</summary>\n" + passes +
                "</details>\n";
    html += "</body>\n</html>\n";
    return html;
}

}  // namespace rl

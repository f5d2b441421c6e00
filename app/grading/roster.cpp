#include "grading/roster.h"

#include "core/error.h"
#include "grading/atomic_file.h"

#include <algorithm>
#include <cctype>
#include <regex>

namespace fs = std::filesystem;

namespace rl {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string trim(const std::string& s) {
    std::size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// Letters and digits only, lower case: "Doe, Jane" -> "doejane" (how Canvas
// names downloads), "Jane  Doe" -> "janedoe".
std::string letters(const std::string& s) {
    std::string out;
    for (unsigned char c : s)
        if (std::isalnum(c) || c >= 0x80) out += char(std::tolower(c));
    return out;
}

// Words, lower case, single spaces: how a Moodle full name is compared.
std::string words(const std::string& s) {
    std::string out;
    bool space = false;
    for (unsigned char c : s) {
        if (std::isalnum(c) || c >= 0x80) {
            if (space && !out.empty()) out += ' ';
            out += char(std::tolower(c));
            space = false;
        } else {
            space = true;
        }
    }
    return out;
}

int column(const std::vector<std::string>& header, std::initializer_list<const char*> names) {
    for (std::size_t k = 0; k < header.size(); ++k)
        for (const char* n : names)
            if (lower(trim(header[k])) == n) return int(k);
    return -1;
}

std::string cell(const std::vector<std::string>& row, int k) {
    return k >= 0 && std::size_t(k) < row.size() ? trim(row[std::size_t(k)]) : "";
}

}  // namespace

std::vector<std::vector<std::string>> parseCsv(const std::string& text, char sep) {
    std::vector<std::vector<std::string>> rows;
    std::vector<std::string> row;
    std::string field;
    bool quoted = false, any = false;
    std::size_t i = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
    for (; i < text.size(); ++i) {
        char c = text[i];
        if (quoted) {
            if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                field += c;
            }
            continue;
        }
        if (c == '"') {
            quoted = true;
            any = true;
        } else if (c == sep) {
            row.push_back(field);
            field.clear();
            any = true;
        } else if (c == '\n' || c == '\r') {
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
            if (any || !field.empty()) {
                row.push_back(field);
                rows.push_back(row);
            }
            row.clear();
            field.clear();
            any = false;
        } else {
            field += c;
            any = true;
        }
    }
    if (any || !field.empty()) {
        row.push_back(field);
        rows.push_back(row);
    }
    return rows;
}

Roster loadRoster(const fs::path& file) {
    const std::string shown = file.string();
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) throw Error(shown + ": roster file not found");
    std::string text = readWholeFile(file);
    // Semicolons where a spreadsheet in a comma-decimal locale saved it (as Canvas's importer accepts).
    std::string firstLine = text.substr(0, text.find('\n'));
    char sep = std::count(firstLine.begin(), firstLine.end(), ';') > std::count(firstLine.begin(), firstLine.end(), ',')
                   ? ';'
                   : ',';
    std::vector<std::vector<std::string>> rows = parseCsv(text, sep);
    if (rows.empty()) throw Error(shown + ": the roster is empty");
    Roster roster;
    roster.file = file;
    roster.headers = rows[0];
    const std::vector<std::string>& h = rows[0];
    if (h.size() >= 2 && trim(h[0]) == "Student" && trim(h[1]) == "ID") {
        roster.kind = Roster::Kind::Canvas;
        int sisUser = column(h, {"sis user id"}), sisLogin = column(h, {"sis login id"}), section = column(h, {"section"});
        if (section < 0) throw Error(shown + ": a Canvas gradebook export has a \"Section\" column; this one has none");
        for (std::size_t r = 1; r < rows.size(); ++r) {
            const std::vector<std::string>& row = rows[r];
            std::string name = cell(row, 0);
            // Not students: the points row, the muted/posting row, Canvas's own test student.
            if (name.find("Points Possible") != std::string::npos) continue;
            if (name == "Student, Test" || name == "Test Student") {
                roster.testStudentLine = int(r) + 1;  // said in the report and the export's report
                continue;
            }
            if (cell(row, 1).empty()) continue;
            RosterStudent s;
            s.name = name;
            s.canvasId = cell(row, 1);
            s.sisUserId = cell(row, sisUser);
            s.sisLoginId = cell(row, sisLogin);
            s.section = cell(row, section);
            s.line = int(r) + 1;
            roster.students.push_back(s);
        }
        return roster;
    }
    int identifier = column(h, {"identifier"}), full = column(h, {"full name"}),
        first = column(h, {"first name", "firstname"}), last = column(h, {"last name", "surname", "lastname"}),
        username = column(h, {"username"}), idNumber = column(h, {"id number", "idnumber"}),
        email = column(h, {"email address", "email"});
    if (full < 0 && first < 0 && username < 0 && idNumber < 0 && email < 0)
        throw Error(shown +
                    ": not a roster raylab can read: expected Canvas's gradebook export (Student, ID, SIS User ID, "
                    "SIS Login ID, Section, ...) or a Moodle export (Full name or First name/Last name, with "
                    "Username, ID number or Email address)");
    roster.kind = Roster::Kind::Moodle;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        const std::vector<std::string>& row = rows[r];
        RosterStudent s;
        s.name = full >= 0 ? cell(row, full) : trim(cell(row, first) + " " + cell(row, last));
        std::string id = cell(row, identifier);
        static const std::regex participant(R"(^\D*(\d+)$)");
        std::smatch m;
        if (std::regex_match(id, m, participant)) s.participantId = m[1];
        s.username = cell(row, username);
        s.idNumber = cell(row, idNumber);
        s.email = cell(row, email);
        s.line = int(r) + 1;
        if (s.name.empty() && s.username.empty() && s.idNumber.empty() && s.email.empty()) continue;
        roster.students.push_back(s);
    }
    return roster;
}

LmsDownloadName parseLmsDownloadName(const std::string& entryName) {
    LmsDownloadName n;
    std::smatch m;
    // Moodle: "<full name>_<participant id>_assignsubmission_<plugin>_<file name or nothing>".
    static const std::regex moodle(R"(^(.+)_(\d+)_assign(?:submission|feedback)_[a-z]+_(.*)$)");
    if (std::regex_match(entryName, m, moodle)) {
        n.kind = LmsDownloadName::Kind::Moodle;
        n.name = m[1];
        n.number = m[2];
        n.file = m[3];
        n.student = n.name + "_" + n.number;
        return n;
    }
    // Canvas (lib/content_zipper.rb): sanitize_file_name of "<sortable name,
    // downcased>[_LATE]_<user id>" (or "[LATE_]anon_<anonymous id>" when the
    // assignment grades anonymously), then "_<attachment id>_<file name>".
    // sanitize_file_name keeps word characters only: Unicode letters and
    // digits, and '_' ("m\u00fcllerj\u00fcrgen", "\u674e\u96f7"); so the name
    // part is every byte that is a lower-case ASCII letter, a digit, '_' or
    // part of a non-ASCII character, and the ids are found at the first
    // "_<digits>_<digits>_" after it (as Canvas itself finds them again when
    // graded files are uploaded).
    static const std::regex anonymous(R"(^(LATE_)?anon_([A-Za-z0-9]+)_(\d+)_([\s\S]+)$)");
    if (std::regex_match(entryName, m, anonymous)) {
        n.kind = LmsDownloadName::Kind::Canvas;
        n.anonymous = true;
        n.late = m[1].matched;
        n.number = m[2];
        n.file = m[4];
        n.student = "anon_" + n.number;
        return n;
    }
    static const std::regex ids(R"(^(_LATE|_late)?_(\d+)_(\d+)_([\s\S]+)$)");
    for (std::size_t end = 0; end < entryName.size(); ++end) {
        const unsigned char c = static_cast<unsigned char>(entryName[end]);
        if (c == '_') {
            const std::string rest = entryName.substr(end);
            if (std::regex_match(rest, m, ids)) {
                n.kind = LmsDownloadName::Kind::Canvas;
                n.name = entryName.substr(0, end);
                n.late = m[1].matched;
                n.number = m[2];
                n.file = m[4];
                n.student = n.name + "_" + n.number;
                return n;
            }
        } else if (!(std::islower(c) || std::isdigit(c) || c >= 0x80)) {
            break;  // not a character sanitize_file_name keeps: no Canvas name
        }
    }
    return n;
}

int matchRosterStudent(const Roster& roster, const std::string& id, const std::string& source, std::string& why) {
    std::vector<int> hits;
    auto collect = [&](auto&& predicate) {
        hits.clear();
        for (std::size_t k = 0; k < roster.students.size(); ++k)
            if (predicate(roster.students[k])) hits.push_back(int(k));
        return hits.size();
    };
    auto ambiguous = [&](const std::string& what) {
        why = what + " fits " + std::to_string(hits.size()) + " students of the roster (lines " +
              std::to_string(roster.students[std::size_t(hits[0])].line) + " and " +
              std::to_string(roster.students[std::size_t(hits[1])].line) + ")";
        return -1;
    };
    // An LMS download name: the number first, then the name.
    for (const std::string& candidate : {source, id}) {
        std::smatch m;
        static const std::regex grouped(R"(^(.*)_(\d+)$)");
        LmsDownloadName n = parseLmsDownloadName(candidate);
        if (n.anonymous) {
            why = "an anonymous Canvas download (anon_" + n.number +
                  "): Canvas gives no user id or name with it, so no roster student can be matched";
            return -1;
        }
        if (n.kind == LmsDownloadName::Kind::None && std::regex_match(candidate, m, grouped)) {
            n.kind = roster.kind == Roster::Kind::Canvas ? LmsDownloadName::Kind::Canvas : LmsDownloadName::Kind::Moodle;
            n.name = m[1];
            n.number = m[2];
        }
        if (n.kind == LmsDownloadName::Kind::Canvas && roster.kind == Roster::Kind::Canvas) {
            if (collect([&](const RosterStudent& s) { return s.canvasId == n.number; }) == 1) return hits[0];
        }
        if (n.kind == LmsDownloadName::Kind::Moodle && roster.kind == Roster::Kind::Moodle) {
            if (collect([&](const RosterStudent& s) { return s.participantId == n.number; }) == 1) return hits[0];
            std::size_t c = collect([&](const RosterStudent& s) { return words(s.name) == words(n.name); });
            if (c == 1) return hits[0];
            if (c > 1) return ambiguous("the name \"" + n.name + "\"");
        }
    }
    // A folder named after one of the student's ids (exact; logins and emails in any case).
    std::size_t c = collect([&](const RosterStudent& s) {
        const std::string l = lower(id);
        return (!s.canvasId.empty() && s.canvasId == id) || (!s.sisUserId.empty() && s.sisUserId == id) ||
               (!s.sisLoginId.empty() && lower(s.sisLoginId) == l) || (!s.username.empty() && lower(s.username) == l) ||
               (!s.idNumber.empty() && s.idNumber == id) || (!s.email.empty() && lower(s.email) == l);
    });
    if (c == 1) return hits[0];
    if (c > 1) return ambiguous("the id \"" + id + "\"");
    // Last: the name, letters only ("doejane" for "Doe, Jane"; "jane-doe" for "Jane Doe").
    c = collect([&](const RosterStudent& s) {
        return !letters(id).empty() && (letters(s.name) == letters(id) || words(s.name) == words(id));
    });
    if (c == 1) return hits[0];
    if (c > 1) return ambiguous("the name \"" + id + "\"");
    why = "no student of the roster " + roster.file.filename().string() + " has the id or name \"" + id + "\"";
    return -1;
}

}  // namespace rl

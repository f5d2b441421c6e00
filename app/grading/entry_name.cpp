#include "grading/entry_name.h"

#include "core/message.h"

#include <cstdint>
#include <cstdio>

namespace rl {

namespace {

// Length of the plain UTF-8 character starting at s[i], or 0 when the bytes
// there are not one (invalid, overlong, surrogate, or a control character).
std::size_t plainCharAt(const std::string& s, std::size_t i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7F) return 0;
    if (c < 0x80) return 1;
    std::size_t n = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c <= 0xDF ? 2 : 0;
    if (n == 0 || (c >= 0xF0 && n != 4) || i + n > s.size()) return 0;
    unsigned long cp = c & (n == 2 ? 0x1F : n == 3 ? 0x0F : 0x07);
    for (std::size_t k = 1; k < n; ++k) {
        const unsigned char d = static_cast<unsigned char>(s[i + k]);
        if ((d & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (d & 0x3F);
    }
    const bool overlong = (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000);
    if (overlong || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) || (cp >= 0x80 && cp <= 0x9F)) return 0;
    if (isBidiControl(std::uint32_t(cp))) return 0;
    return n;
}

}  // namespace

bool isPlainUtf8(const std::string& name) {
    for (std::size_t i = 0; i < name.size();) {
        const std::size_t n = plainCharAt(name, i);
        if (n == 0) return false;
        i += n;
    }
    return true;
}

std::string escapedName(const std::string& name) {
    if (isPlainUtf8(name)) return name;
    std::string out;
    for (std::size_t i = 0; i < name.size();) {
        const std::size_t n = name[i] == '%' ? 0 : plainCharAt(name, i);
        if (n > 0) {
            out.append(name, i, n);
            i += n;
            continue;
        }
        char hex[4];
        std::snprintf(hex, sizeof hex, "%%%02X", static_cast<unsigned char>(name[i]));
        out += hex;
        ++i;
    }
    return out;
}

std::string safeEntryId(const std::string& name) {
    std::string id = escapedName(name);
    if (id.size() <= kMaxEntryIdBytes) return id;
    // Cut where a character (and an %XX escape) begins, then the name's hash:
    // distinct long names stay distinct, and the same name gives the same id on every run.
    std::size_t cut = kMaxEntryIdBytes - 17;
    while (cut > 0 && (static_cast<unsigned char>(id[cut]) & 0xC0) == 0x80) --cut;
    if (cut >= 1 && id[cut - 1] == '%')
        cut -= 1;
    else if (cut >= 2 && id[cut - 2] == '%')
        cut -= 2;
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bit, of the name's bytes
    for (unsigned char c : name) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char tail[24];
    std::snprintf(tail, sizeof tail, "~%016llx", static_cast<unsigned long long>(h));
    return id.substr(0, cut) + tail;
}

bool isGraderOutputName(const std::string& id) {
    static const char* const kNames[] = {".",           "..",          ".lock",        ".shader-cache", "grades.csv",
                                         "index.html",  "summary.json", "rubric.json", "students.txt",  "_reference"};
    for (const char* n : kNames)
        if (id == n) return true;
    const std::string merging = ".merging";
    return id.rfind("grades-", 0) == 0 ||
           (id.size() >= merging.size() && id.compare(id.size() - merging.size(), merging.size(), merging) == 0);
}

std::string graderSafeId(const std::string& id) { return isGraderOutputName(id) ? "student-" + id : id; }

std::string hexBytes(const std::string& bytes) {
    std::string out;
    for (unsigned char c : bytes) {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%s%02x", out.empty() ? "" : " ", c);
        out += hex;
    }
    return out;
}

}  // namespace rl

#include "server/labs/Gradebook.h"
#include "server/NumberText.h"

#include <string_view>

namespace tlmhub::server {

std::string spreadsheetSafeCell(const std::string& text)
{
    // A spreadsheet reads a field starting with these as a formula (a tab or carriage return
    // may precede one); an apostrophe before it makes it text. A field starts at the cell's
    // start and after any character an import may split on (it may be set to split on ';' or
    // tabs, and not honour the quotes), spaces after it included.
    constexpr std::string_view kFormulaStart = "=+-@\t\r";
    constexpr std::string_view kFieldBreaks = ",;\t|\r\n";
    std::string cell;
    bool fieldStart = true;
    for (const char c : text) {
        if (fieldStart && kFormulaStart.find(c) != std::string_view::npos) cell += '\'';
        cell += c;
        fieldStart = kFieldBreaks.find(c) != std::string_view::npos || (fieldStart && c == ' ');
    }
    if (cell.find_first_of(",\"\r\n") == std::string::npos) return cell;
    std::string quoted = "\"";
    for (char c : cell) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + '"';
}

std::string gradebookCsv(const std::vector<std::string>& assignmentTitles, const std::vector<GradebookRow>& rows)
{
    std::string csv = "student";
    for (const std::string& title : assignmentTitles) {
        csv += ',';
        csv += spreadsheetSafeCell(title);
        csv += ',';
        csv += spreadsheetSafeCell(title + " late");
    }
    csv += ",total\n";
    // Numbers are printed by us, never taken from a user, so they go out as numbers: only the
    // names and titles need neutralising.
    for (const GradebookRow& row : rows) {
        csv += spreadsheetSafeCell(row.student);
        double total = 0.0;
        for (const GradebookCell& cell : row.cells) {
            csv += ',';
            if (cell.points) {
                csv += numberText(*cell.points);
                total += *cell.points;
            }
            csv += cell.late ? ",late" : ",";
        }
        csv += ',';
        csv += numberText(total);
        csv += '\n';
    }
    return csv;
}

} // namespace tlmhub::server

#include "server/labs/Gradebook.h"

#include <cstdio>
#include <string_view>

namespace tlmhub::server {

namespace {

std::string number(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

} // namespace

std::string spreadsheetSafeCell(const std::string& text)
{
    std::string cell = text;
    // A spreadsheet reads a cell starting with these as a formula (a tab or carriage return
    // may precede one); the apostrophe makes it text.
    if (!cell.empty() && std::string_view("=+-@\t\r").find(cell.front()) != std::string_view::npos)
        cell.insert(cell.begin(), '\'');
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
                csv += number(*cell.points);
                total += *cell.points;
            }
            csv += cell.late ? ",late" : ",";
        }
        csv += ',';
        csv += number(total);
        csv += '\n';
    }
    return csv;
}

} // namespace tlmhub::server

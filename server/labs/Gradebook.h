#pragma once
// A class's gradebook as CSV: one row per student, one column per assignment (the teacher's
// grade where set, else the check score of the latest hand-in; empty when none), a late
// marker and a total. Every cell is neutralised against spreadsheet formula injection.
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

struct GradebookCell {
    std::optional<double> points;        // nullopt: not handed in
    bool late = false;
};

struct GradebookRow {
    std::string student;
    std::vector<GradebookCell> cells;    // one per assignment, in the column order
};

// A cell a spreadsheet shows as text: a =, +, -, @, tab or carriage return that starts the
// cell, or follows a comma, semicolon, tab, bar or line break (spaces between), gets an
// apostrophe before it; then quoted per RFC 4180 when it holds a comma, quote or line break.
std::string spreadsheetSafeCell(const std::string& text);

// Header: student, then per assignment "<title>" and "<title> late", then total.
std::string gradebookCsv(const std::vector<std::string>& assignmentTitles, const std::vector<GradebookRow>& rows);

} // namespace tlmhub::server

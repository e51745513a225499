#pragma once
// hopsancli: a command line that takes HopsanCLI's options (docs/hopsancli.md), so that a
// script written for HopsanCLI runs tlmhub with only the program's path changed. Its parts:
// the option table and parser (Arguments.cpp), the result and parameter files
// (ResultFiles.cpp, ParameterFiles.cpp), and the run itself (main.cpp).
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace tlmhub {
class Component;
class System;
} // namespace tlmhub

namespace tlmhub::hopsancli {

// HopsanCLI prints its own errors and warnings on stdout as "Error: ..." and "Warning: ...";
// --silent keeps them (and everything else hopsancli prints on stdout) back.
struct Printer {
    bool silent = false;
    void line(const std::string& text) const;
    void error(const std::string& text) const { line("Error: " + text); }
    void warning(const std::string& text) const { line("Warning: " + text); }
};

// ---- arguments ----
enum class OptionKind { Switch, Value, Repeatable };
// What hopsancli does with an option HopsanCLI has: acts on it, accepts it and says it has
// no effect here, or refuses the run (HopsanCLI's exit code for a failure, 1).
enum class Support { Supported, NoEffect, Refused };

struct OptionSpec {
    const char* shortName;   // "" when there is none
    const char* longName;
    OptionKind kind;
    Support support;
    const char* valueName;   // for the usage text
    const char* help;
};

const std::vector<OptionSpec>& optionTable();

struct Arguments {
    // Long name -> values in the order given (a switch has one empty value).
    std::map<std::string, std::vector<std::string>> given;
    bool has(const std::string& longName) const { return given.count(longName) != 0; }
    std::string value(const std::string& longName, const std::string& fallback = "") const;
    const std::vector<std::string>& values(const std::string& longName) const;
};

enum class ParseOutcome { Run, Exit };
// Parses argv as HopsanCLI's parser does ("-m FILE", "--hmf FILE"; a value option at most
// once; "--" ends the options). --help and --version print and give Exit with code 0; a
// parse error prints HopsanCLI's "PARSE ERROR" text on stderr and gives Exit with code 1.
ParseOutcome parseArguments(int argc, char** argv, Arguments& out, int& exitCode);

// ---- model lookups as HopsanCLI names things ----
// "Sub1$Sub2$Comp" from the root; prints HopsanCLI's error and gives null when a part of
// the name does not exist.
Component* componentWithFullName(System& root, const std::string& fullName, const Printer& print);

// ---- result files (core.md §4.5) ----
enum class ResultAmount { Full, Final };
// `only` holds full port names ("Sub$Comp#Port") or variable names ("Comp#Port#Var"); empty
// keeps every logged variable. `columns` writes the transpose ("--resultsCSVSort cols").
// False with `error` set when the file cannot be written.
bool writeResultsCsv(const System& root, const std::string& path, ResultAmount amount,
                     const std::vector<std::string>& only, bool columns, std::string& error);

// ---- parameter files: "Name,value" lines ----
// Every parameter's value string: "self#P" for the root's system parameters ("Sub$#P" for a
// subsystem's), "Comp#P" / "Sub$Comp#Port#Var" for component parameters and start values.
// `prefix` goes before every name (--prefixRootSystemName gives "Root$").
bool exportParameters(const System& root, const std::string& path, const std::string& prefix,
                      std::string& error);
// Sets each named parameter; a name or value that is not taken is reported as HopsanCLI
// reports it, and the lines after it still apply.
void importParameters(System& root, const std::string& path, const Printer& print);

// Splits as HopsanCLI does (std::getline on the delimiter: no trailing empty field).
std::vector<std::string> splitFields(const std::string& text, char delimiter);

} // namespace tlmhub::hopsancli

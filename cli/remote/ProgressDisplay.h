#pragma once
// Progress of a job or study while the remote commands wait for it, on stderr. On a
// terminal: one bar redrawn in place. Piped (a log, CI): a plain line at each further 10 %.
#include <cstdio>
#include <string>

namespace tlmhub::cli::remote {

class ProgressDisplay {
public:
    // `label` starts every line, e.g. "job 12".
    explicit ProgressDisplay(std::string label, std::FILE* out = stderr);
    ~ProgressDisplay();
    ProgressDisplay(const ProgressDisplay&) = delete;
    ProgressDisplay& operator=(const ProgressDisplay&) = delete;

    // `fraction` from 0 to 1; `detail` follows the percentage (e.g. "37/100 runs").
    void update(double fraction, const std::string& detail = {});
    // Ends the bar's line on a terminal, so later output starts on a line of its own.
    void finish();

private:
    std::string mLabel;
    std::FILE* mOut;
    bool mTerminal;
    int mTenthsShown = -1;      // piped: the last 10 % step printed
    std::string mSuffixShown;   // piped: the detail printed with it
    std::string mDrawn;         // terminal: the bar as last drawn
};

} // namespace tlmhub::cli::remote

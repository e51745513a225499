#include "cli/remote/ProgressDisplay.h"

#include <algorithm>
#include <cmath>
#include <unistd.h>

namespace tlmhub::cli::remote {

ProgressDisplay::ProgressDisplay(std::string label, std::FILE* out)
    : mLabel(std::move(label)), mOut(out), mTerminal(::isatty(::fileno(out)) == 1)
{
}

ProgressDisplay::~ProgressDisplay() { finish(); }

void ProgressDisplay::update(double fraction, const std::string& detail)
{
    fraction = std::clamp(std::isfinite(fraction) ? fraction : 0.0, 0.0, 1.0);
    const int percent = static_cast<int>(std::floor(fraction * 100.0));
    const std::string suffix = detail.empty() ? "" : " " + detail;
    if (!mTerminal) {
        const int tenths = percent / 10;
        // At 100 % a study may still be running: its final state gets a line of its own.
        const bool newState = tenths == 10 && suffix != mSuffixShown;
        if (tenths <= mTenthsShown && !newState) return;
        mTenthsShown = tenths;
        mSuffixShown = suffix;
        std::fprintf(mOut, "%s: %d %%%s\n", mLabel.c_str(), tenths * 10, suffix.c_str());
        std::fflush(mOut);
        return;
    }
    constexpr int width = 30;
    const int filled = static_cast<int>(fraction * width);
    const std::string bar = mLabel + " [" + std::string(filled, '#') + std::string(width - filled, '.') + "] " +
                            std::to_string(percent) + " %" + suffix;
    if (bar == mDrawn) return;
    // Spaces over the rest of a longer previous line.
    const std::size_t clear = mDrawn.size() > bar.size() ? mDrawn.size() - bar.size() : 0;
    std::fprintf(mOut, "\r%s%s", bar.c_str(), std::string(clear, ' ').c_str());
    std::fflush(mOut);
    mDrawn = bar;
}

void ProgressDisplay::finish()
{
    if (mTerminal && !mDrawn.empty()) std::fputc('\n', mOut);
    mDrawn.clear();
}

} // namespace tlmhub::cli::remote

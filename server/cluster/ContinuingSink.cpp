#include "server/cluster/ContinuingSink.h"

#include <algorithm>

namespace tlmhub::server {

namespace {

void appendFrom(const std::vector<double>& values, std::size_t at, std::size_t delivered, std::vector<double>& out)
{
    // values[k] is the stream's sample at + k; those before `delivered` were had already.
    const std::size_t skip = delivered > at ? std::min(delivered - at, values.size()) : 0;
    out.insert(out.end(), values.begin() + static_cast<std::ptrdiff_t>(skip), values.end());
}

} // namespace

ContinuingSink::ContinuingSink(std::int64_t jobId, std::vector<std::string> wanted, StreamSink out)
    : mJobId(jobId), mWanted(std::move(wanted)), mOut(std::move(out))
{
}

StreamSink ContinuingSink::newStream()
{
    std::uint64_t stream = 0;
    {
        std::lock_guard lock(mMutex);
        stream = ++mStream;
        mStreamTime = 0;
        mStreamAt.assign(mDelivered.size(), 0);
    }
    StreamSink sink;
    sink.progress = [this, stream](nlohmann::json event) {
        std::lock_guard lock(mMutex);
        if (stream == mStream && !mFinished) mOut.progress(std::move(event));
    };
    sink.frame = [this, stream](StreamFrame f) { frame(stream, std::move(f)); };
    sink.done = [this, stream](nlohmann::json event) {
        std::lock_guard lock(mMutex);
        if (stream != mStream || mFinished) return;
        mFinished = true;
        mOut.done(std::move(event));
    };
    return sink;
}

void ContinuingSink::frame(std::uint64_t stream, StreamFrame f)
{
    std::lock_guard lock(mMutex);
    if (stream != mStream || mFinished || !f.layout) return;
    if (!mLayout) {
        mLayout = f.layout;
        mDelivered.assign(mLayout->names.size(), 0);
        mStreamAt.assign(mLayout->names.size(), 0);
    }
    StreamFrame out;
    out.jobId = mJobId;
    out.layout = mLayout;
    // The usual case: a stream past everything delivered, in the same layout: its samples go
    // on as they are (shared, not copied).
    bool allNew = mStreamTime >= mTimeDelivered && f.layout->names == mLayout->names;
    for (std::size_t i = 0; allNew && i < mDelivered.size(); ++i) allNew = mStreamAt[i] >= mDelivered[i];
    if (allNew) {
        for (const auto& part : f.parts) {
            mStreamTime += part->time.size();
            for (std::size_t i = 0; i < mStreamAt.size(); ++i)
                mStreamAt[i] += i < part->columns.size() ? part->columns[i].size() : 0;
        }
        out.parts = std::move(f.parts);
    } else {
        // Columns by name: the new stream's layout should be the same, but a variable it lacks
        // just gets no samples.
        std::vector<std::ptrdiff_t> from(mLayout->names.size(), -1);
        for (std::size_t i = 0; i < from.size(); ++i) {
            const auto& names = f.layout->names;
            const auto it = std::find(names.begin(), names.end(), mLayout->names[i]);
            if (it != names.end()) from[i] = it - names.begin();
        }
        auto samples = std::make_shared<FrameSamples>();
        samples->columns.resize(from.size());
        for (const auto& part : f.parts) {
            appendFrom(part->time, mStreamTime, mTimeDelivered, samples->time);
            mStreamTime += part->time.size();
            for (std::size_t i = 0; i < from.size(); ++i) {
                if (from[i] < 0 || static_cast<std::size_t>(from[i]) >= part->columns.size()) continue;
                const auto& column = part->columns[static_cast<std::size_t>(from[i])];
                appendFrom(column, mStreamAt[i], mDelivered[i], samples->columns[i]);
                mStreamAt[i] += column.size();
            }
        }
        if (samples->empty()) return;
        out.parts.push_back(std::move(samples));
    }
    mTimeDelivered = std::max(mTimeDelivered, mStreamTime);
    for (std::size_t i = 0; i < mDelivered.size(); ++i) mDelivered[i] = std::max(mDelivered[i], mStreamAt[i]);
    bool any = false;
    for (const auto& part : out.parts) any = any || !part->empty();
    if (any) mOut.frame(std::move(out));
}

void ContinuingSink::finishFromTable(const ResultTable* table, JobState state, const std::string& error)
{
    std::lock_guard lock(mMutex);
    if (mFinished) return;
    mFinished = true;
    if (table) {
        if (!mLayout) {
            // As StreamHub::resolveLayout: the wanted variables the result has, else its first ones.
            std::vector<std::string> names;
            if (mWanted.empty()) {
                for (const auto& c : table->columns) {
                    if (names.size() == StreamHub::kMaxFrameVariables) break;
                    names.push_back(c.name);
                }
            } else {
                for (const auto& name : mWanted) {
                    if (names.size() == StreamHub::kMaxFrameVariables) break;
                    if (table->hasColumn(name) && std::find(names.begin(), names.end(), name) == names.end())
                        names.push_back(name);
                }
            }
            mLayout = std::make_shared<const FrameLayout>(std::move(names));
            mDelivered.assign(mLayout->names.size(), 0);
        }
        auto samples = std::make_shared<FrameSamples>();
        if (mTimeDelivered < table->time.size())
            samples->time.assign(table->time.begin() + static_cast<std::ptrdiff_t>(mTimeDelivered), table->time.end());
        samples->columns.resize(mLayout->names.size());
        for (std::size_t i = 0; i < mLayout->names.size(); ++i) {
            const ResultColumn* column = table->column(mLayout->names[i]);
            if (!column) continue;
            // As TableFrameSource::count: never more samples than the time vector has.
            const std::size_t count = std::min(column->data.size(), table->time.size());
            if (mDelivered[i] < count)
                samples->columns[i].assign(column->data.begin() + static_cast<std::ptrdiff_t>(mDelivered[i]),
                                           column->data.begin() + static_cast<std::ptrdiff_t>(count));
            mDelivered[i] = std::max(mDelivered[i], count);
        }
        mTimeDelivered = std::max(mTimeDelivered, table->time.size());
        if (!samples->empty()) {
            StreamFrame out;
            out.jobId = mJobId;
            out.layout = mLayout;
            out.parts.push_back(std::move(samples));
            mOut.frame(std::move(out));
        }
    }
    // As StreamHub::sendDone.
    nlohmann::json done = {{"type", "event.done"}, {"job_id", mJobId}, {"state", jobStateName(state)}};
    if (!error.empty()) done["error"] = error;
    mOut.done(std::move(done));
}

void ContinuingSink::forwardDone(nlohmann::json event)
{
    std::lock_guard lock(mMutex);
    if (mFinished) return;
    mFinished = true;
    mOut.done(std::move(event));
}

bool ContinuingSink::finished() const
{
    std::lock_guard lock(mMutex);
    return mFinished;
}

std::vector<std::string> ContinuingSink::layoutNames() const
{
    std::lock_guard lock(mMutex);
    return mLayout ? mLayout->names : std::vector<std::string>{};
}

std::size_t ContinuingSink::timeDelivered() const
{
    std::lock_guard lock(mMutex);
    return mTimeDelivered;
}

} // namespace tlmhub::server

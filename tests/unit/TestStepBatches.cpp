// The step loop's batches (core/StepBatches.h): components of one type run side by side,
// but never out of order where they are linked within the list.
#include "TestHelpers.h"

#include "core/StepBatches.h"

namespace tlmhub::test {
namespace {

std::vector<std::string> namesOf(const std::vector<Component*>& components)
{
    std::vector<std::string> names;
    for (const Component* c : components) names.push_back(c->name());
    return names;
}

// Two copies of Step -> Gain, added one copy after the other.
void addTwoStepGainPairs(System& root)
{
    add(root, "SignalStep", "Step1");
    add(root, "SignalGain", "Gain1");
    add(root, "SignalStep", "Step2");
    add(root, "SignalGain", "Gain2");
    connectOk(root, "Step1", "out", "Gain1", "in");
    connectOk(root, "Step2", "out", "Gain2", "in");
}

TEST(StepBatches, IndependentComponentsOfOneTypeShareABatch)
{
    System root;
    addTwoStepGainPairs(root);
    const StepBatches batches(root.componentsInOrder(), StepBatches::Order::Regroup);
    EXPECT_EQ(namesOf(batches.components()), (std::vector<std::string>{"Step1", "Step2", "Gain1", "Gain2"}));
    EXPECT_EQ(batches.batchCount(), 2u);
}

TEST(StepBatches, KeepOrderOnlyJoinsNeighboursOfOneType)
{
    System root;
    addTwoStepGainPairs(root);
    const StepBatches batches(root.componentsInOrder(), StepBatches::Order::Keep);
    EXPECT_EQ(namesOf(batches.components()), (std::vector<std::string>{"Step1", "Gain1", "Step2", "Gain2"}));
    EXPECT_EQ(batches.batchCount(), 4u);
}

// Gain1 -> Add -> Gain2: grouping by type alone would run Gain2 before the Add it reads.
TEST(StepBatches, LinkedComponentsKeepTheirListOrder)
{
    System root;
    add(root, "SignalGain", "Gain1");
    add(root, "SignalAdd", "Add");
    add(root, "SignalGain", "Gain2");
    add(root, "SignalGain", "Lone");
    connectOk(root, "Gain1", "out", "Add", "in1");
    connectOk(root, "Add", "out", "Gain2", "in");
    const StepBatches batches(root.componentsInOrder(), StepBatches::Order::Regroup);
    EXPECT_EQ(namesOf(batches.components()), (std::vector<std::string>{"Gain1", "Lone", "Add", "Gain2"}));
    EXPECT_EQ(batches.batchCount(), 3u);
}

// A component made without the factory has no batch step: it runs by its virtual call.
class CountingComponent : public ComponentSignal {
public:
    void simulateOneTimestep() override { ++steps; }
    int steps = 0;
};

TEST(StepBatches, AComponentWithoutBatchStepRunsByItsVirtualCall)
{
    CountingComponent first, second;
    const StepBatches batches({&first, &second}, StepBatches::Order::Regroup);
    batches.step(0.25);
    batches.step(0.5);
    EXPECT_EQ(first.steps, 2);
    EXPECT_EQ(second.steps, 2);
    EXPECT_EQ(second.time(), 0.5);
    EXPECT_EQ(batches.batchCount(), 1u);
}

} // namespace
} // namespace tlmhub::test

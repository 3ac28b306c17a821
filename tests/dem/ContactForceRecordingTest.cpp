// Contact forces kept on request (DemSystem::ContactForceRecording): between requests the
// pair pass keeps the slots' histories and only the loads of the bodies two workers share
// (pass B1 gathers those). The trajectory must not notice, on any pair path or thread
// count, and the requested step must list the contacts every_step lists.
#include "dem/DemSystem.h"
#include "TestSystems.h"

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

using namespace geocomp::dem;

namespace {

using Recording = DemSystem::ContactForceRecording;

/// test::compressed_box (two and three workers share bodies) with the given recording.
void make_specimen(DemSystem& sys, const ContactModel& law, bool batched, int threads, Recording recording)
{
  test::compressed_box(sys, law, batched, threads);
  sys.set_contact_force_recording(recording);
}

/// The state's bits after 1200 steps (the last one recorded), then every contact's ids,
/// overlap and force.
std::vector<double> run_and_record(const ContactModel& law, bool batched, int threads, Recording recording)
{
  DemSystem sys;
  make_specimen(sys, law, batched, threads, recording);
  sys.run(1199);
  sys.record_contact_forces();
  sys.run(1);
  std::vector<double> bits = test::state_bits(sys, true);
  for (std::size_t w = 0; w < 6; ++w) bits.insert(bits.end(), sys.wall(w).force.data(), sys.wall(w).force.data() + 3);
  const std::vector<ContactRecord> contacts = sys.contacts();
  EXPECT_GT(contacts.size(), 200u);
  for (const ContactRecord& c : contacts) {
    bits.insert(bits.end(), {double(c.wall), double(c.i), double(c.j), c.overlap});
    bits.insert(bits.end(), c.force.data(), c.force.data() + 3);
  }
  return bits;
}

}  // namespace

TEST(ContactForceRecording, OnRequestKeepsTheTrajectoryBitsAndListsTheRequestedStep)
{
  const ContactModel laws[] = {test::linear_law(1e5, 0.5),
                               HertzMindlin(HertzNormal({1e8, 0.25, HertzNormal::Damping::restitution, 0.5, 0.0, true}),
                                            MindlinTangential({1e8, 0.25, 1.0}))};
  struct Case
  {
    const ContactModel* law;
    bool batched;
    const char* name;
  };
  const Case cases[] = {{&laws[0], true, "linear, batched"}, {&laws[0], false, "linear, scalar"}, {&laws[1], false, "Hertz-Mindlin"}};
  for (const Case& c : cases) {
    const std::vector<double> every = run_and_record(*c.law, c.batched, 1, Recording::every_step);
    for (int threads = 1; threads <= 3; ++threads)
      EXPECT_TRUE(test::bitwise_equal(every, run_and_record(*c.law, c.batched, threads, Recording::on_request)))
        << c.name << ", " << threads << " threads";
  }
}

TEST(ContactForceRecording, ContactsRefuseAStepThatDidNotRecord)
{
  DemSystem sys;
  make_specimen(sys, test::linear_law(1e5, 0.5), true, 2, Recording::on_request);
  sys.run(300);
  ASSERT_GT(sys.n_touching_pairs(), 100u);
  EXPECT_FALSE(sys.contact_forces_current());
  EXPECT_THROW(sys.contacts(), std::logic_error);
  sys.record_contact_forces();
  sys.run(1);
  EXPECT_TRUE(sys.contact_forces_current());
  EXPECT_GT(sys.contacts().size(), 100u);
  sys.run(1);  // the request served one step
  EXPECT_THROW(sys.contacts(), std::logic_error);
  sys.set_contact_force_recording(Recording::every_step);
  sys.run(1);
  EXPECT_GT(sys.contacts().size(), 100u);
}

// A checkpoint written between requests holds the slots' histories, the loads as they
// are and the recording state: the restored system refuses contacts() as the original
// does, and both continue with the same bits and record the same contacts.
TEST(ContactForceRecording, CheckpointCarriesTheRecordingState)
{
  DemSystem sys;
  make_specimen(sys, test::linear_law(1e5, 0.5), true, 2, Recording::on_request);
  sys.run(400);
  std::stringstream state;
  sys.write_state(state);
  DemSystem restored;
  restored.read_state(state);
  EXPECT_EQ(restored.contact_force_recording(), Recording::on_request);
  EXPECT_THROW(restored.contacts(), std::logic_error);
  for (DemSystem* s : {&sys, &restored}) {
    s->run(99);
    s->record_contact_forces();
    s->run(1);
  }
  EXPECT_TRUE(test::bitwise_equal(test::state_bits(sys, true), test::state_bits(restored, true)));
  const std::vector<ContactRecord> a = sys.contacts(), b = restored.contacts();
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 100u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].i, b[k].i);
    EXPECT_EQ(a[k].force, b[k].force);
  }
}

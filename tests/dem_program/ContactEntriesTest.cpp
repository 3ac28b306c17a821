// The linear law's constants, each given one way in the case file (issue 30): c_n in N s/m,
// from the restitution, or per unit effective mass as LIGGGHTS' gamma_n; k_t in N/m or as a
// ratio of k_n; c_t in N s/m, as a ratio of c_n, or by default c_n k_t/k_n (S0 eq. (2)).
// gamma_n standing for a restitution gives that restitution's collision; a constant given
// two ways is refused naming the entry.
#include "ContactCase.h"

#include "compare/case/CaseDescription.h"
#include "dem/program/DemEngine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace geocomp;
using namespace geocomp::dem;

namespace {
CaseDescription case_with(const std::string &contact) { return test::contact_case(contact, "entries.prm"); }

const LinearSpringDashpot &linear(const ContactModel &m) { return std::get<LinearSpringDashpot>(m); }

/// Two equal spheres (R = 5 mm, rho = 2650) meeting head on at 0.1 m/s each: the ratio of
/// the separation speed after the contact to the approach speed before it.
double rebound(const ContactModel &law)
{
  DemSystem s;
  s.add_box(Vec3::Constant(-1.0), Vec3::Constant(1.0), 0.0);
  const ParticleId a = s.add_sphere(Vec3(-0.0051, 0, 0), 0.005, 2650.0, Vec3(0.1, 0, 0));
  const ParticleId b = s.add_sphere(Vec3(0.0051, 0, 0), 0.005, 2650.0, Vec3(-0.1, 0, 0));
  s.set_contact_model(law);
  s.set_time_step(0.01 * s.critical_time_step());
  for (int k = 0; k < 200000; ++k) {
    s.step();
    const Vec3 va = s.particles().v[s.index_of(a)], vb = s.particles().v[s.index_of(b)];
    const double gap = (s.particles().x[s.index_of(b)] - s.particles().x[s.index_of(a)]).norm() - 0.01;
    if (gap > 1e-4 && vb.x() > va.x())
      return (vb.x() - va.x()) / 0.2;
  }
  ADD_FAILURE() << "the spheres did not separate";
  return 0.0;
}

/// The CaseError of a case text, or "" when it is accepted.
std::string refusal(const std::string &contact)
{
  try {
    case_with(contact);
  } catch (const CaseError &e) {
    return e.parameter;
  }
  return "";
}
} // namespace

TEST(ContactEntries, LiggghtsGammaNGivesTheCollisionOfTheRestitutionItStandsFor)
{
  const double e = 0.5, k_n = 1e5;
  const double m_eff = 0.5 * 4.0 / 3.0 * M_PI * 0.005 * 0.005 * 0.005 * 2650.0;
  const double zeta = -std::log(e) / std::sqrt(M_PI * M_PI + std::log(e) * std::log(e)); // DEM-NOTES section 3
  const double gamma_n = 2.0 * zeta * std::sqrt(k_n / m_eff);                          // c_n / m*
  const CaseDescription from_e = case_with("  set restitution = 0.5\n");
  const CaseDescription from_gamma = case_with("  set normal damping per mass = " + std::to_string(gamma_n) + "\n");
  const double given = from_gamma.contact.normal_damping_per_mass; // gamma_n as printed, 6 decimals
  EXPECT_NEAR(given, gamma_n, 1e-6);
  const LinearNormal &n = linear(make_contact_model(from_gamma.contact)).normal();
  EXPECT_EQ(n.parameters().damping_input, LinearNormal::Damping::per_unit_mass);
  EXPECT_EQ(n.damping(m_eff, k_n), given * m_eff);
  const double e_restitution = rebound(make_contact_model(from_e.contact));
  const double e_gamma = rebound(make_contact_model(from_gamma.contact));
  // The same collision (gamma_n printed to 6 digits), and the clamped law's restitution of
  // DEM-NOTES section 3's table (target 0.5: 0.550).
  EXPECT_NEAR(e_gamma, e_restitution, 1e-5);
  EXPECT_NEAR(e_restitution, 0.550, 0.005);
  std::printf("[contact] gamma_n %.6g 1/s: rebound %.6f, from e = 0.5: %.6f\n", gamma_n, e_gamma, e_restitution);
}

TEST(ContactEntries, TangentialStiffnessAndDampingReachTheLawEachWayTheyAreGiven)
{
  // The default: k_t = (2/7) k_n and c_t = (2/7) c_n, in the proportion of the springs.
  const LinearTangential::Parameters d = linear(make_contact_model(case_with("").contact)).tangential().parameters();
  EXPECT_TRUE(d.stiffness_is_ratio && d.damping_is_ratio);
  EXPECT_NEAR(d.k_t, 2.0 / 7.0, 1e-12);
  EXPECT_EQ(d.c_t, d.k_t);
  // k_t in N/m: the default dashpot follows k_t/k_n = 0.5.
  const LinearTangential::Parameters t =
    linear(make_contact_model(case_with("  set tangential stiffness = 5e4\n").contact)).tangential().parameters();
  EXPECT_FALSE(t.stiffness_is_ratio);
  EXPECT_EQ(t.k_t, 5e4);
  EXPECT_TRUE(t.damping_is_ratio);
  EXPECT_EQ(t.c_t, 0.5);
  // c_t as a ratio (0: no tangential dashpot; 1: LIGGGHTS' gamma_t = gamma_n) or in N s/m.
  const auto c_t_of = [](const std::string &entry) {
    return linear(make_contact_model(case_with(entry).contact)).tangential().parameters().c_t;
  };
  EXPECT_EQ(c_t_of("  set tangential damping ratio = 0\n"), 0.0);
  EXPECT_EQ(c_t_of("  set tangential damping ratio = 1\n"), 1.0);
  const LinearTangential::Parameters c =
    linear(make_contact_model(case_with("  set tangential damping = 3\n").contact)).tangential().parameters();
  EXPECT_FALSE(c.damping_is_ratio);
  EXPECT_EQ(c.c_t, 3.0);
  // S0's own choice, k_t = k_n: c_t = c_n.
  const LinearTangential::Parameters s0 =
    linear(make_contact_model(case_with("  set tangential stiffness ratio = 1\n").contact)).tangential().parameters();
  EXPECT_EQ(s0.k_t, 1.0);
  EXPECT_EQ(s0.c_t, 1.0);
}

TEST(ContactEntries, AConstantGivenTwoWaysIsRefusedNamingTheEntry)
{
  EXPECT_EQ(refusal("  set normal damping = 2\n  set normal damping per mass = 100\n"),
            "contact/normal damping per mass");
  EXPECT_EQ(refusal("  set tangential stiffness = 5e4\n  set tangential stiffness ratio = 1\n"),
            "contact/tangential stiffness");
  EXPECT_EQ(refusal("  set tangential damping = 3\n  set tangential damping ratio = 1\n"),
            "contact/tangential damping");
  EXPECT_EQ(refusal("  set model = hertz-mindlin\n  set tangential damping ratio = 1\n"),
            "contact/tangential damping ratio");
  EXPECT_EQ(refusal("  set normal damping per mass = 100\n"), "");
  // k_t in N/m with S0's k_n formula leaves the default dashpot ratio undefined.
  try {
    parse_case("set engines = dem\nsubsection contact\n  set tangential stiffness = 5e4\nend\n"
               "subsection program\n  subsection stage 1\n    set z = rate -1\n    set stop when = eps_zz <= -0.01\n"
               "    set max duration = 1\n  end\nend\n",
               "entries.prm");
    FAIL() << "accepted";
  } catch (const CaseError &e) {
    EXPECT_EQ(e.parameter, "contact/tangential damping ratio");
  }
}

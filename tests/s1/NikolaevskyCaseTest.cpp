// continuum/model = nikolaevsky through the case-file path: a case text is parsed
// (parse_case), turned into the material (material_from_case, make_material_factory) and
// driven on the material point by the ProgramRunner, exactly as `geocomp material-point`
// does. Every number checked is a closed form of S1's parameters written next to it
// (tension positive; J1 = tr sigma, tau = sqrt(J2); omega = alpha/3, m_c = 1/sqrt3 - omega):
//   first yield (S1 eq. (1)) in triaxial compression at lateral -p0, axial -p0 - q:
//     omega (-3 p0 - q) + q/sqrt3 = Y0 = m_c sigma_y  =>  q_y = (Y0 + 3 omega p0) / m_c
//   hardened surface  Phi = Y0 + H kappa,  H = m_c (sigma_c - sigma_y)(1/sqrt3 - Lambda/3) / eps_p*
//   flow (S1 eq. (2))  tr(d eps^p) = 2 Lambda sqrt(I2(d e^p)),  I2 = e:e/2,  d kappa = 2 sqrt(I2)
//   uniaxial hardening |sigma_zz| = sigma_y + (sigma_c - sigma_y) |eps^p_zz| / eps_p*.
#include "common/ProgramRunner.h"
#include "compare/case/CaseDescription.h"
#include "continuum/driver/CaseMaterial.h"
#include "continuum/driver/MaterialPointEngine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace geocomp;

namespace {

const double inv_sqrt3 = 1.0 / std::sqrt(3.0);

/// The parameters the closed forms use, as a user would read them off S1's table.
struct Row {
  std::string block; ///< the case file's `subsection nikolaevsky` body
  double E, nu, sigma_y, sigma_c, alpha, Lambda, eps_p;
  double omega() const { return alpha / 3.0; }
  double m_c() const { return inv_sqrt3 - omega(); }
  double Y0() const { return m_c() * sigma_y; }
  double H() const { return m_c() * (sigma_c - sigma_y) * (inv_sqrt3 - Lambda / 3.0) / eps_p; }
};

// S1's table, sandstone and concrete rows; eps_p* = 0.1 (sigma_c - sigma_y)/E (our assumption).
const Row sandstone{"set material = sandstone\n", 16e9, 0.28, 40e6, 70e6, 0.57, 0.36, 2e-4};
const Row concrete{"set material = concrete\n", 38.6e9, 0.194, 21.8e6, 45.8e6, 0.63, 0.0, 6e-5};
const Row custom{"set material = custom\nset youngs modulus = 30e9\nset poisson ratio = 0.2\n"
                 "set yield stress = 60e6\nset compressive strength = 90e6\nset internal friction = 0.45\n"
                 "set dilatancy = 0.2\nset plastic strain at strength = 1e-4\n",
                 30e9, 0.2, 60e6, 90e6, 0.45, 0.2, 1e-4};

/// Triaxial compression: x, y held at -p0 (the initial isotropic stress), z shortened
/// until eps_zz <= -strain, in about 400 samples. Small strain: S1's closed forms are
/// written in it (at S1's strains of a few 1e-3 finite strain differs by that fraction).
CaseDescription triaxial_case(const Row &row, double p0, double strain)
{
  const double rate = 1e-3;
  std::ostringstream t;
  t.precision(17);
  t << "set engines = material-point\n"
    << "subsection specimen\n  set box size = 0.05\n  set isotropic pressure = " << p0 << "\nend\n"
    << "subsection continuum\n  set model = nikolaevsky\n  set kinematics = small strain\n"
    << "  subsection nikolaevsky\n" << row.block << "  end\nend\n"
    << "subsection program\n  set sampling interval = " << strain / rate / 400.0 << "\n"
    << "  subsection stage 1\n    set x = stress " << -p0 << "\n    set y = stress " << -p0
    << "\n    set z = rate " << -rate << "\n    set stop when = eps_zz <= " << -strain
    << "\n    set max duration = " << 2.0 * strain / rate << "\n  end\nend\n";
  return parse_case(t.str(), "nikolaevsky_case.prm");
}

/// What `geocomp material-point` does with a case (compare/cli/Engines.cpp).
Response run_point(const CaseDescription &c)
{
  continuum::MaterialPointParameters p;
  p.initial_stress = -c.specimen.isotropic_pressure;
  p.substeps_per_advance = c.continuum.point_substeps;
  p.kinematics = continuum::parse_kinematics(c.continuum.kinematics);
  continuum::MaterialPointEngine engine(continuum::material_from_case(c.continuum), p);
  return ProgramRunner(c.program, engine).run();
}

double J1(const Tensor3 &s) { return s.trace(); }
double tau(const Tensor3 &s)
{
  const Tensor3 dev = s - s.trace() / 3.0 * Tensor3::Identity();
  return std::sqrt(0.5 * (dev.array() * dev.array()).sum());
}
double mises_schleicher(const Row &row, const Tensor3 &s) { return row.omega() * J1(s) + tau(s); } // S1 eq. (1)

/// Plastic strain from the recorded strain and stress by isotropic Hooke (strain from the
/// program start, stress from the initial isotropic -p0).
Tensor3 plastic_strain(const Row &row, const ResponseSample &s, double p0)
{
  const Tensor3 ds = s.stress + p0 * Tensor3::Identity();
  const Tensor3 elastic = ((1.0 + row.nu) * ds - row.nu * ds.trace() * Tensor3::Identity()) / row.E;
  return s.strain - elastic;
}

/// Yielded: kappa > 0. (Not the state flag, which is the region of the last sub-increment of
/// the sample; MaterialPointEngine::advance_to can end a sample with a round-off-sized
/// increment that stays elastic.)
bool plastic(const Response &r, const ResponseSample &s) { return s.extras[r.extra_index("kappa")] > 0.0; }

} // namespace

TEST(NikolaevskyCase, SelectedModelYieldsOnTheMisesSchleicherSurface)
{
  for (const Row *row : {&sandstone, &concrete, &custom})
    for (const double p0 : {0.0, 20e6}) {
      SCOPED_TRACE(row->block + "p0 = " + std::to_string(p0));
      const double q_y = (row->Y0() + 3.0 * row->omega() * p0) / row->m_c(); // S1 eq. (1), closed form
      if (p0 == 0.0) {
        EXPECT_NEAR(q_y / row->sigma_y, 1.0, 1e-12); // uniaxial compression yields at S1's sigma_y
      }
      const CaseDescription c = triaxial_case(*row, p0, 2.0 * q_y / row->E);
      const Response r = run_point(c);
      ASSERT_GT(r.samples.size(), 300u);
      std::size_t first = 0;
      for (std::size_t i = 0; i < r.samples.size() && first == 0; ++i)
        if (plastic(r, r.samples[i]))
          first = i;
      ASSERT_GT(first, 1u) << "never yielded";
      for (std::size_t i = 0; i < first; ++i) { // elastic: Hooke with the row's E, below the surface
        const ResponseSample &s = r.samples[i];
        EXPECT_NEAR(s.stress(2, 2), -p0 + row->E * s.strain(2, 2), 1e-9 * q_y);
        EXPECT_LT(mises_schleicher(*row, s.stress), row->Y0() * (1.0 + 1e-12));
      }
      // First yield between the last elastic sample and the first plastic one (0.5 % apart).
      const double q_before = -p0 - r.samples[first - 1].stress(2, 2);
      const double q_after = -p0 - r.samples[first].stress(2, 2);
      EXPECT_LE(q_before, q_y * (1.0 + 1e-9));
      EXPECT_GE(q_after, q_y * (1.0 - 1e-9));
      EXPECT_LT(q_after - q_before, 0.006 * q_y);
      // Every plastic sample on the hardened Mises-Schleicher surface.
      const int k_kappa = r.extra_index("kappa");
      for (std::size_t i = first; i < r.samples.size(); ++i) {
        const ResponseSample &s = r.samples[i];
        EXPECT_NEAR(mises_schleicher(*row, s.stress), row->Y0() + row->H() * s.extras[k_kappa], 1e-8 * row->Y0());
      }
    }
}

TEST(NikolaevskyCase, PlasticStrainIncrementsFollowTheNikolaevskyDilatancy)
{
  for (const Row *row : {&sandstone, &custom}) {
    SCOPED_TRACE(row->block);
    const double p0 = 20e6;
    const double q_y = (row->Y0() + 3.0 * row->omega() * p0) / row->m_c();
    const Response r = run_point(triaxial_case(*row, p0, 4.0 * q_y / row->E));
    const int k_kappa = r.extra_index("kappa"), k_vol = r.extra_index("plastic_volumetric_strain");
    int checked = 0;
    for (std::size_t i = 1; i < r.samples.size(); ++i) {
      const ResponseSample &a = r.samples[i - 1], &b = r.samples[i];
      if (!plastic(r, a))
        continue;
      const Tensor3 d = plastic_strain(*row, b, p0) - plastic_strain(*row, a, p0);
      const Tensor3 e = d - d.trace() / 3.0 * Tensor3::Identity();
      const double root_I2 = std::sqrt(0.5 * (e.array() * e.array()).sum());
      ASSERT_GT(root_I2, 0.0);
      EXPECT_NEAR(d.trace() / (2.0 * root_I2), row->Lambda, 1e-6); // S1 eq. (2)
      EXPECT_NEAR(b.extras[k_kappa] - a.extras[k_kappa], 2.0 * root_I2, 1e-6 * 2.0 * root_I2);
      // The point's own record agrees: tr eps^p = Lambda kappa.
      EXPECT_NEAR(b.extras[k_vol], plastic_strain(*row, b, p0).trace(), 1e-12);
      EXPECT_NEAR(b.extras[k_vol], row->Lambda * b.extras[k_kappa], 1e-12);
      ++checked;
    }
    EXPECT_GT(checked, 200);
  }
}

TEST(NikolaevskyCase, UniaxialStressHardensLinearlyToTheCompressiveStrengthAtTheAssumedPlasticStrain)
{
  const Row &row = sandstone;
  const Response r = run_point(triaxial_case(row, 0.0, row.sigma_c / row.E + 2.0 * row.eps_p));
  double largest = 0.0;
  for (const ResponseSample &s : r.samples) {
    if (!plastic(r, s))
      continue;
    const double eps_p_axial = -plastic_strain(row, s, 0.0)(2, 2);
    EXPECT_NEAR(-s.stress(2, 2), row.sigma_y + (row.sigma_c - row.sigma_y) * eps_p_axial / row.eps_p,
                1e-8 * row.sigma_c);
    largest = std::max(largest, eps_p_axial);
  }
  EXPECT_GT(largest, row.eps_p); // the run passed sigma_c
}

TEST(NikolaevskyCase, CohesionFactorScalesTheWholeHardeningLawSofteningScaleChangesNothing)
{
  const Row &row = sandstone;
  const auto factory =
    continuum::make_material_factory(continuum::material_from_case(triaxial_case(row, 0.0, 1e-3).continuum));
  const double f = 0.8;
  const auto base = factory->make({});
  const auto weak = factory->make({f, 1.0});
  EXPECT_EQ(weak->name(), "nikolaevsky");
  const auto uniaxial = [](double s) {
    continuum::Vector6 v = continuum::Vector6::Zero();
    v(2) = -s;
    return v;
  };
  // kappa at sigma_c in uniaxial compression: |eps^p_zz| = kappa (1/sqrt3 - Lambda/3) = eps_p*.
  const double kappa_c = row.eps_p / (inv_sqrt3 - row.Lambda / 3.0);
  EXPECT_NEAR(weak->yield_function(uniaxial(f * row.sigma_y), 0.0), 0.0, 1e-9 * row.Y0());
  EXPECT_NEAR(weak->yield_function(uniaxial(f * row.sigma_c), kappa_c), 0.0, 1e-9 * row.Y0());
  EXPECT_NEAR(base->yield_function(uniaxial(row.sigma_c), kappa_c), 0.0, 1e-9 * row.Y0());
  // Linear hardening never softens: the crack-band stretch leaves the model as it is.
  const auto stretched = factory->make({1.0, 3.0});
  continuum::Vector6 eps;
  eps << 1.2e-3, 1.5e-3, -1.5e-2, 6e-4, -3e-4, 9e-4;
  const auto u0 = base->update(eps, {}), u1 = stretched->update(eps, {});
  ASSERT_NE(u0.region, continuum::ReturnRegion::elastic);
  EXPECT_EQ((u0.stress - u1.stress).norm(), 0.0);
  EXPECT_EQ(u0.history.kappa, u1.history.kappa);
}

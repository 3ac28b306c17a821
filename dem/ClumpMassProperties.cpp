#include "dem/ClumpMassProperties.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace geocomp::dem {

double default_voxel_size(const std::vector<ClumpMember>& members)
{
  double r_min = std::numeric_limits<double>::infinity();
  for (const ClumpMember& m : members) r_min = std::min(r_min, m.radius);
  return 2.0 * r_min / 20.0;  // S4: cube side D_min / 20
}

ClumpMassProperties voxel_mass_properties(const std::vector<ClumpMember>& members, double cell)
{
  if (members.empty()) throw std::invalid_argument("voxel_mass_properties: no members");
  for (const ClumpMember& m : members)
    if (!(m.radius > 0.0) || !m.centre.allFinite())
      throw std::invalid_argument("voxel_mass_properties: member with a non-positive radius");
  const double h = cell > 0.0 ? cell : default_voxel_size(members);
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const ClumpMember& m : members) {
    lo = lo.cwiseMin(m.centre - Vec3::Constant(m.radius));
    hi = hi.cwiseMax(m.centre + Vec3::Constant(m.radius));
  }
  const Vec3 extent = hi - lo;
  const long nx = long(std::ceil(extent.x() / h)), ny = long(std::ceil(extent.y() / h)),
             nz = long(std::ceil(extent.z() / h));
  if (double(nx) * double(ny) * double(nz) > 2147483648.0)
    throw std::invalid_argument("voxel_mass_properties: grid too fine");
  // Centre the grid on the bounding box; moments about the box centre keep sums small.
  const Vec3 ref = 0.5 * (lo + hi);
  const Vec3 origin = ref - 0.5 * h * Vec3(double(nx), double(ny), double(nz));
  double count = 0.0;
  Vec3 first = Vec3::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // sum of r r^T about ref
  for (long i = 0; i < nx; ++i) {
    const double x = origin.x() + (double(i) + 0.5) * h;
    for (long j = 0; j < ny; ++j) {
      const double y = origin.y() + (double(j) + 0.5) * h;
      for (long k = 0; k < nz; ++k) {
        const Vec3 c(x, y, origin.z() + (double(k) + 0.5) * h);
        bool inside = false;
        for (const ClumpMember& m : members)
          if ((c - m.centre).squaredNorm() < m.radius * m.radius) { inside = true; break; }
        if (!inside) continue;
        const Vec3 r = c - ref;
        count += 1.0;
        first += r;
        second += r * r.transpose();
      }
    }
  }
  if (count == 0.0) throw std::invalid_argument("voxel_mass_properties: cell larger than the members");
  const double dv = h * h * h;
  ClumpMassProperties p;
  p.volume = count * dv;                                       // S4 eq. (1)
  const Vec3 d = first / count;
  p.centroid = ref + d;                                        // S4 eq. (2)
  // Second moment about the centroid, then I = tr(S) 1 - S plus the cubes' own inertia.
  const Eigen::Matrix3d S = dv * (second - count * d * d.transpose());
  p.inertia = S.trace() * Eigen::Matrix3d::Identity() - S +
              (count * dv * h * h / 6.0) * Eigen::Matrix3d::Identity();  // S4 eq. (3)
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(p.inertia);
  if (eig.info() != Eigen::Success) throw std::runtime_error("voxel_mass_properties: eigen-solver failed");
  p.principal_moments = eig.eigenvalues();
  p.axes = eig.eigenvectors();
  if (p.axes.determinant() < 0.0) p.axes.col(2) = -p.axes.col(2);  // right-handed body frame
  return p;
}

double lens_volume(double R1, double R2, double d)
{
  if (d >= R1 + R2) return 0.0;
  const double rs = std::min(R1, R2);
  if (d <= std::abs(R1 - R2)) return 4.0 / 3.0 * M_PI * rs * rs * rs;
  const double g = R1 + R2 - d;
  return M_PI * g * g * (d * d + 2.0 * d * (R1 + R2) - 3.0 * (R1 - R2) * (R1 - R2)) / (12.0 * d);
}

}  // namespace geocomp::dem

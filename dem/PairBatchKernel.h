// @sect3{The batched pair kernel of the linear spring-dashpot law (S0 eq. (1)-(2))}
//
// Why it exists: the particle-pair loop of pass A (ContactLists.h) is the engine's hot
// loop, and for S0's law, `LinearSpringDashpot` = LinearNormal x LinearTangential, it was
// bound by the latency of one contact at a time (a division, two square roots and three
// data-dependent branches per contact: apart/touching, the frame-rotation series, stick/slip).
// This kernel evaluates four pair slots at once in 256-bit vectors (AVX2), with every
// branch turned into a lane select, so the unpredictable branches disappear and the
// divisions and roots of four contacts share one instruction. The contact test runs first
// on every slot, four at a time; the touching slots (three in four of a dense packing's
// list, the rest lie within the Verlet skin) are packed into a ring with what the test
// computed, and the stages run only on them, in groups of eight full batches: kinematics;
// normal law and spring rotation; Coulomb cap, outputs and loads; each stage over the
// eight batches before the next, so that the processor overlaps the long dependency chains
// of independent batches. The touching slots keep their ascending order, so every body's
// loads are still added in slot order.
//
// It is the same law as the scalar path, operation for operation:
// sphere_sphere_kinematics (ContactKinematics.h), LinearNormal::evaluate,
// rotate_into_tangent_plane (TangentialFrame.h), LinearTangential::evaluate and
// ContactLaw::evaluate, written in the same order with the same roundings (IEEE +, -, *,
// /, sqrt are exact-rounded in both, and the kernel is compiled without FMA contraction).
// So a slot gets the same bits from either path; the test
// `PairBatchKernel.EqualsTheScalarLawBitForBit` holds the two to that, over touching, apart,
// new, sliding and sticking contacts. Each lane depends on its own slot only, so the result
// is independent of how slots fall into batches and threads (determinism is unchanged).
//
// This header is free of Eigen on purpose: the kernel's translation unit is compiled
// with -mavx2, and Eigen compiled with another instruction set in one program would
// break the one-definition rule (its alignment of Quaterniond changes with AVX). The
// caller passes raw arrays (Vec3 arrays are three contiguous doubles per particle) and
// the slot layout below, which DemSystem.cpp checks against PairSlot with static_asserts.
//
// Bodies: a slot's two bodies are read by index, four lanes at a time. The caller packs
// each body's position with its radius and its velocity with its inverse mass into 32-byte
// records (PackedBody) before the pass, so one aligned load per body and lane, and one 4x4
// transpose for four lanes, bring both the vector and the scalar the kernel needs with it
// (from the separate arrays that took a masked load of the vector, which crosses a cache
// line for one body in four, and a scalar gather). The spins stay in their array.
//
// Loads: with `rows`, each slot's force and torques are then added into its two bodies'
// rows in slot order, exactly as LoadScatter::add_pair does (the same bits as the gather).
//
// Wall slots: the particle-wall contacts of unbounded plane walls run through the same
// stages 2 and 3 after their own test (h < R, h the distance of the centre from the plane)
// and kinematics (sphere_wall_kinematics), the wall's velocity and mu_p per lane.
//
// Availability: `pair_batch_kernel_available()` is true when the kernel was compiled
// (x86-64 with a compiler that takes -mavx2) and the processor has AVX2; otherwise
// DemSystem uses the scalar path, which gives the same numbers.
#pragma once

#include <cstddef>
#include <cstdint>

namespace geocomp::dem {

/// Byte layout of a pair slot as the kernel reads and writes it (PairSlot, ContactLists.h).
struct PairSlotLayout
{
  std::size_t size = 0;                 ///< sizeof(PairSlot)
  std::size_t i = 0, j = 0;             ///< offsets of the two uint32 storage indices
  /// Offset of the history: the overlap and the three doubles of the spring, consecutive
  /// (one 256-bit load or store per slot).
  std::size_t history = 0;
};

/// The constants of a LinearSpringDashpot law, as the scalar parts use them.
struct LinearLawConstants
{
  bool stiffness_direct = true;   ///< k_n given in N/m (else S0's formula through `stiffness`)
  double k_n = 0.0;
  /// S0's k_n(m*, R*) for `stiffness_direct == false` (LinearNormal::stiffness); pure, so the
  /// kernel calls it once per distinct (m*, R*) it meets in a row.
  double (*stiffness)(const void* normal_part, double m_eff, double r_eff) = nullptr;
  const void* normal_part = nullptr;
  enum class Damping { direct, per_unit_mass, restitution } damping = Damping::restitution;
  double c_n = 0.0, gamma_n = 0.0, zeta = 0.0;
  bool clamp_tensile = true;
  bool k_t_is_ratio = true;
  double k_t = 0.0;
  bool c_t_is_ratio = true;
  double c_t = 0.0;
};

/// Four doubles of one body, 32-byte aligned (a 3-vector and a scalar).
struct alignas(32) PackedBody
{
  double q[4];
};

/// Particle arrays (storage order) and the slots of one call.
struct PairBatchArgs
{
  const double* omega = nullptr;  ///< the spins, 3 per particle
  /// The bodies as the kernel reads them (DemSystem packs them before pass A): x, y, z, R
  /// and v_x, v_y, v_z, 1/m, so that one aligned load per body brings a vector and the
  /// scalar the kernel needs with it.
  const PackedBody* position_radius = nullptr;
  const PackedBody* velocity_inv_mass = nullptr;
  unsigned char* slots = nullptr; ///< the PairSlot array
  PairSlotLayout layout;
  /// The slots' loads (SlotLoad, ContactLists.h: force then lever, 6 doubles a slot),
  /// written for every touching slot when `record_loads`, else only for the slots with a
  /// shared body (their loads are gathered in pass B), and zeroed for slots that come apart.
  double* loads = nullptr;
  bool record_loads = true;
  LinearLawConstants law;
  double mu = 0.0;                ///< Coulomb coefficient between particles
  double dt = 0.0;                ///< history increment (0: evaluate without advancing)
  bool track_losses = false;
  /// Software prefetch of the slots and the j bodies a few batches ahead of the test
  /// (DemSystem::set_prefetch: for lists larger than the last-level cache).
  bool prefetch = false;
  /// Where the slots' loads are added (LoadScatter.h): rows of 8 doubles (force, 0,
  /// torque, 0; 64-byte aligned), the row of each body (`shared`: one of this worker's
  /// eight junk rows from `junk_row` on, one per lane and side). No rows: the slots are
  /// only written.
  double* rows = nullptr;
  const std::uint32_t* row_of = nullptr;
  std::uint32_t shared = 0, junk_row = 0;
  /// Wall slots (evaluate_linear_walls_batched): the slots are WallSlots, whose layout is a
  /// PairSlot's with i the wall and j the particle (their loads always recorded); the
  /// unbounded plane walls as arrays (point, normal and velocity: 3 per wall; the Coulomb
  /// coefficient mu_p: 1 per wall).
  const double* wall_point = nullptr;
  const double* wall_normal = nullptr;
  const double* wall_velocity = nullptr;
  const double* wall_mu = nullptr;
};

/// Energy dissipated by the slots of one call (summed lane by lane, then over the lanes).
struct PairBatchLosses
{
  double damping = 0.0, friction = 0.0;
};

/// True when the batched kernel exists in this build and runs on this processor.
bool pair_batch_kernel_available();

/// Evaluates slots [begin, end) of `args.slots`; returns their losses when
/// `args.track_losses`. Precondition: pair_batch_kernel_available().
PairBatchLosses evaluate_linear_pairs_batched(const PairBatchArgs& args, std::size_t begin, std::size_t end);

/// The same law on wall slots [begin, end) against unbounded plane walls
/// (sphere_wall_kinematics, then ContactLaw::evaluate; the same bits as the scalar path).
/// The slots' loads are not added anywhere (pass B sums them per body). Precondition:
/// pair_batch_kernel_available() and the wall arrays of `args` set.
PairBatchLosses evaluate_linear_walls_batched(const PairBatchArgs& args, std::size_t begin, std::size_t end);

}  // namespace geocomp::dem

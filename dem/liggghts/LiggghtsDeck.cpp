#include "dem/liggghts/LiggghtsDeck.h"
#include "dem/liggghts/LiggghtsDeckParts.h"

#include "common/AtomicFile.h"
#include "common/case/CaseError.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace geocomp::dem {

namespace fs = std::filesystem;

namespace deck {

std::string num(double v)
{
  std::ostringstream o;
  o.precision(17);
  o << v;
  return o.str();
}

void write_text(const fs::path &file, const std::string &text)
{
  write_atomically(file, [&](const fs::path &tmp) {
    std::ofstream out(tmp);
    out << text;
    if (!out)
      throw std::runtime_error(file.string() + ": could not be written");
  });
}

namespace {
/// Face w (xlo..zhi) of the box as two triangles reaching a quarter edge beyond it.
std::string face_stl(const Packing &p, int w)
{
  const int a = w / 2, b = (a + 1) % 3, c = (a + 2) % 3;
  const Eigen::Vector3d L = p.box_max - p.box_min;
  const double at = w % 2 ? p.box_max[a] : p.box_min[a];
  auto corner = [&](int i, int j) {
    Eigen::Vector3d v;
    v[a] = at;
    v[b] = i ? p.box_max[b] + 0.25 * L[b] : p.box_min[b] - 0.25 * L[b];
    v[c] = j ? p.box_max[c] + 0.25 * L[c] : p.box_min[c] - 0.25 * L[c];
    return "      vertex " + num(v[0]) + " " + num(v[1]) + " " + num(v[2]) + "\n";
  };
  const int tri[2][3][2] = {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 1}, {0, 1}}};
  std::string s = "solid " + std::string(kWall[w]) + "\n";
  for (const auto &t : tri) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (const auto &v : t)
      s += corner(v[0], v[1]);
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid " + kWall[w] + "\n";
}
} // namespace

/// The deck's condition for one stop condition, or CaseError for one it cannot test.
std::string condition_expression(const Condition &c, const std::string &where, const std::string &file)
{
  std::string q;
  switch (c.quantity) {
  case Quantity::Time: q = "v_t"; break;
  case Quantity::StageTime: q = "(v_t-v_t0)"; break;
  case Quantity::EpsXX: q = "v_ex"; break;
  case Quantity::EpsYY: q = "v_ey"; break;
  case Quantity::EpsZZ: q = "v_ez"; break;
  case Quantity::SigXX: q = "v_sx"; break;
  case Quantity::SigYY: q = "v_sy"; break;
  case Quantity::SigZZ: q = "v_sz"; break;
  case Quantity::GammaMax: q = "v_gamma_max"; break;
  case Quantity::TauMax: q = "v_tau_max"; break;
  case Quantity::VolumetricStrain: q = "v_ev"; break;
  case Quantity::MeanStress: q = "((v_sx+v_sy+v_sz)/3)"; break;
  default:
    throw CaseError(file, where, "'" + c.text + "': the LIGGGHTS deck tests time, stage_time, strains, stresses, "
                                   "gamma_max, tau_max, volumetric strain and mean stress; peak_drop, stress_ratio "
                                   "and servo_error need a history it does not keep");
  }
  return "(" + q + (c.at_least ? ">=" : "<=") + num(c.value) + ")";
}

/// Box geometry, stresses and strains, the same every stage.
std::string geometry_section(const Packing &p, const LiggghtsContact &law)
{
  std::ostringstream o;
  o << "# ---- the box: wall positions (mesh reference points), edges, strains, wall stresses\n"
       "variable dt equal dt\nvariable t equal (step-1)*dt\nvariable nowstep equal step\n"
       "variable zero equal 0.0\ncompute rad all property/atom radius\n";
  for (int a = 0; a < 3; ++a) {
    const char x = kAxis[a];
    const char b = kAxis[(a + 1) % 3], c = kAxis[(a + 2) % 3];
    o << "variable " << x << "lo equal f_w_" << x << "lo[" << 7 + a << "]\n"
      << "variable " << x << "hi equal f_w_" << x << "hi[" << 7 + a << "]\n"
      << "variable L" << x << " equal v_" << x << "hi-v_" << x << "lo\n"
      << "variable L0" << x << " equal " << num(p.box_max[a] - p.box_min[a]) << "\n"
      << "variable e" << x << " equal (v_L" << x << "-v_L0" << x << ")/v_L0" << x << "\n"
      << "variable A" << x << " equal v_L" << b << "*v_L" << c << "\n"
      << "variable s" << x << " equal -(f_w_" << x << "hi[" << 1 + a << "]-f_w_" << x << "lo[" << 1 + a
      << "])/(2*v_A" << x << ")\n";
    // The servo's stress: LIGGGHTS' setup of each `run` adds the wall forces once more
    // (f_w doubles), so from that setup to the end of the first step the servo reads the
    // normal forces kept at the end of the previous run (keep_forces()).
    for (const char *side : {"lo", "hi"})
      o << "variable uF_" << x << side << " equal (step<=v_nrun+1)*v_kF_" << x << side << "+(step>v_nrun+1)*f_w_" << x
        << side << "[" << 1 + a << "]\n";
    o << "variable us" << x << " equal -(v_uF_" << x << "hi-v_uF_" << x << "lo)/(2*v_A" << x << ")\n";
    for (int side = 0; side < 2; ++side) { // sum of the normal stiffness of the wall's touching spheres
      const std::string w = std::string(1, x) + (side ? "hi" : "lo");
      const std::string delta = side ? "(" + std::string(1, x) + "+c_rad-v_" + w + ")"
                                     : "(c_rad-" + std::string(1, x) + "+v_" + w + ")";
      std::string k = law.wall_stiffness_expression;
      for (std::size_t at; (at = k.find("DELTA")) != std::string::npos;)
        k.replace(at, 5, "abs" + delta);
      o << "variable k_" << w << " atom (" << delta << ">0)*" << k << "\n"
        << "compute K_" << w << " all reduce sum v_k_" << w << "\n";
    }
  }
  o << "variable ev equal (1+v_ex)*(1+v_ey)*(1+v_ez)-1\n"
       "variable emax equal 0.5*(v_ex+0.5*(v_ey+v_ez+abs(v_ey-v_ez))+abs(v_ex-0.5*(v_ey+v_ez+abs(v_ey-v_ez))))\n"
       "variable emin equal 0.5*(v_ex+0.5*(v_ey+v_ez-abs(v_ey-v_ez))-abs(v_ex-0.5*(v_ey+v_ez-abs(v_ey-v_ez))))\n"
       "variable gamma_max equal v_emax-v_emin\n"
       "variable smax equal 0.5*(v_sx+0.5*(v_sy+v_sz+abs(v_sy-v_sz))+abs(v_sx-0.5*(v_sy+v_sz+abs(v_sy-v_sz))))\n"
       "variable smin equal 0.5*(v_sx+0.5*(v_sy+v_sz-abs(v_sy-v_sz))-abs(v_sx-0.5*(v_sy+v_sz-abs(v_sy-v_sz))))\n"
       "variable tau_max equal 0.5*(v_smax-v_smin)\n";
  // The shear stresses, symmetrised: sigma_ab = 1/2 (sigma_ab + sigma_ba), sigma_ba from the
  // b-forces on the walls normal to a (the unloading branches' deviator needs them).
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3;
    const std::string x(1, kAxis[a]), y(1, kAxis[b]);
    o << "variable s" << x << y << " equal -0.5*((f_w_" << x << "hi[" << b + 1 << "]-f_w_" << x << "lo[" << b + 1
      << "])/(2*v_A" << x << ")+(f_w_" << y << "hi[" << a + 1 << "]-f_w_" << y << "lo[" << a + 1 << "])/(2*v_A" << y
      << "))\n";
  }
  return o.str();
}

/// Target strain of kinematic axis a at program time T (StageControl::strain; direction +1
/// loading, -1 an unloading branch: every rate reversed from the anchor t0, e0).
std::string strain_expression(const Stage &s, int a, const std::string &T, double direction)
{
  const std::string dt = "(" + num(direction) + "*(" + T + "-v_t0))";
  if (!s.isochoric)
    return "(v_e0" + std::string(1, kAxis[a]) + "+" + num(s.axes[a].value) + "*" + dt + ")";
  const std::string ex = "(v_e0x-" + num(s.isochoric_rate) + "*" + dt + ")";
  const std::string ey = "(v_e0y-" + num(s.lambda * s.isochoric_rate) + "*" + dt + ")";
  if (a == 0)
    return ex;
  if (a == 1)
    return ey;
  return "((1+v_e0x)*(1+v_e0y)*(1+v_e0z)/((1+" + ex + ")*(1+" + ey + "))-1)"; // S0 eq. (3): L_z = V0/(L_x L_y)
}

/// After each `run`: the step and the walls' normal forces, for the next run's first step.
std::string keep_forces()
{
  std::string o = "variable nrun equal ${nowstep}\n";
  for (int w = 0; w < 6; ++w)
    o += std::string("variable kF_") + kWall[w] + " equal ${F" + kAxis[w / 2] + "_" + kWall[w] + "}\n";
  return o;
}

/// The column names of samples.txt and the print text of one row.
std::pair<std::string, std::string> sample_columns()
{
  std::string cols = "t stage branch", vals = "${t} ${stage} ${branch}";
  for (const char *v : {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi", "Lx", "Ly", "Lz", "sx", "sy", "sz", "ke", "erot"}) {
    cols += std::string(" ") + v;
    vals += std::string(" ${") + v + "}";
  }
  for (int w = 0; w < 6; ++w)
    for (int a = 0; a < 3; ++a) {
      const std::string name = std::string("F") + kAxis[a] + "_" + kWall[w];
      cols += " " + name;
      vals += " ${" + name + "}";
    }
  return {cols, vals};
}

/// One stress axis' servo (AxisServo::velocity) as variables; defines v<a> for the stage.
std::string servo_variables(char x, double goal, const LiggghtsDeckInput &in)
{
  const std::string X(1, x), g = num(goal), gp = num(in.servo.proportional_gain), gi = num(in.servo.integral_gain);
  std::ostringstream o;
  o << "variable err" << X << " equal " << g << "-v_us" << X << "\n"
    << "variable K" << X << " equal 0.5*(c_K_" << X << "lo+c_K_" << X << "hi)*(1+" << num(in.contact.dashpot_time)
    << "/v_dt)\n"
    << "variable G" << X << " equal v_A" << X << "/(v_K" << X << "*v_dt+(v_K" << X << "<=0))\n"
    << "variable I" << X << " equal f_I" << X << "*(step-v_n0)\n" // learned speed: running mean x samples
    << "variable Itry" << X << " equal v_I" << X << "+" << gi << "*v_G" << X << "*v_err" << X << "\n"
    << "variable vtry" << X << " equal " << gp << "*v_G" << X << "*v_err" << X << "+v_Itry" << X << "\n"
    << "variable inc" << X << " equal (v_K" << X << ">0)*((abs(v_vtry" << X << ")<v_vmax)||(abs(v_Itry" << X
    << ")<abs(v_I" << X << ")))*(0.5*(abs(v_Itry" << X << "+v_vmax)-abs(v_Itry" << X << "-v_vmax))-v_I" << X
    << ")-(v_K" << X << "<=0)*v_I" << X << "\n"
    << "variable v" << X << " equal (v_K" << X << ">0)*0.5*(abs(" << gp << "*v_G" << X << "*v_err" << X << "+v_I" << X
    << "+v_vmax)-abs(" << gp << "*v_G" << X << "*v_err" << X << "+v_I" << X << "-v_vmax))+(v_K" << X
    << "<=0)*v_vmax*((v_err" << X << ">0)-(v_err" << X << "<0))\n"
    << "fix I" << X << " all ave/time 1 1 1 v_inc" << X << " ave running\n";
  return o.str();
}

std::string kinematic_and_servo_variables(const Stage &s, double direction, const LiggghtsDeckInput &in)
{
  std::ostringstream o;
  std::string kin = "0";
  for (int a = 0; a < 3; ++a)
    if (s.kinematic(a)) {
      const std::string X(1, kAxis[a]);
      o << "variable v" << X << " equal 0.5*(v_L0" << X << "*(1+"
        << strain_expression(s, a, "(step-1)*v_dt", direction) << ")-v_L" << X << ")/v_dt\n";
      kin = "0.5*(" + kin + "+abs(v_v" + X + ")+abs(" + kin + "-abs(v_v" + X + ")))"; // max
    }
  const std::string cap = num(in.servo.max_velocity), ratio = num(in.servo.kinematic_speed_ratio);
  o << "variable vkin equal " << kin << "\n"
    << "variable vmax equal 0.5*(" << cap << "+" << ratio << "*v_vkin+abs(" << cap << "-" << ratio << "*v_vkin))\n";
  for (int a = 0; a < 3; ++a)
    if (!s.kinematic(a))
      o << servo_variables(kAxis[a], s.axes[a].value, in);
  return o.str();
}

std::string branch_name(int stage, int trigger)
{
  return "branch_" + std::to_string(stage) + "_" + std::to_string(trigger);
}

namespace {
/// The block after each main-path sample that fires trigger k of stage `index` once: the
/// branch gets the next id, the run writes a restart file and the state the branch deck
/// needs beside it (LiggghtsBranchDeck.cpp), and branches.txt says where it left.
std::string trigger_block(const Stage &s, int index, int k, const LiggghtsDeckInput &in)
{
  const std::string where = "program/stage " + std::to_string(index) + "/unload at";
  const std::string tag = std::to_string(index) + "_" + std::to_string(k + 1);
  const std::string name = branch_name(index, k + 1);
  std::ostringstream o;
  o << "variable trig" << tag << " equal " << condition_expression(s.unload_at[k].condition, where, in.case_file)
    << "\n"
    << "if \"${fired" << tag << "} > 0 || ${trig" << tag << "} == 0\" then \"jump SELF skip" << tag << "\"\n"
    << "variable nbranch equal ${nbranch}+1\nvariable fired" << tag << " equal 1\n"
    << "write_restart " << name << ".restart\n";
  std::vector<std::string> state = {"variable branch equal ${nbranch}", "variable nrun equal ${nowstep}",
                                    "variable t0 equal ${t}"};
  for (int w = 0; w < 6; ++w)
    state.push_back(std::string("variable kF_") + kWall[w] + " equal ${kF_" + kWall[w] + "}");
  for (const char *v : {"ex", "ey", "ez"})
    state.push_back(std::string("variable e0") + v[1] + " equal ${" + v + "}");
  for (const char *v : {"sx", "sy", "sz", "sxy", "syz", "szx"}) {
    state.push_back(std::string("variable O") + v + " equal ${" + v + "}");  // where the branch leaves
    state.push_back(std::string("variable S") + v + " equal ${S0" + v + "}"); // where the stage began
  }
  state.push_back("variable taustart equal ${tau_max}");
  for (std::size_t i = 0; i < state.size(); ++i)
    o << "print \"" << state[i] << "\" " << (i ? "append " : "file ") << name << ".state screen no\n";
  o << "print \"start ${nbranch} " << index - 1 << " " << k << " ${t}\" append branches.txt screen no\n"
    << "label skip" << tag << "\n";
  return o.str();
}
} // namespace

std::string stage_section(const Stage &s, int index, long long steps_per_sample, double dt,
                          const LiggghtsDeckInput &in)
{
  const std::string where = "program/stage " + std::to_string(index);
  std::ostringstream o;
  o << "# ---- stage " << index << ": " << s.name << "\n"
    << "variable stage equal " << index - 1 << "\n"
    << "variable n0 equal ${nowstep}\nvariable t0 equal ${t}\n"
    << "variable e0x equal ${ex}\nvariable e0y equal ${ey}\nvariable e0z equal ${ez}\n";
  if (!s.unload_at.empty()) { // the stress the stage starts from: the branches' default target
    for (const char *v : {"sx", "sy", "sz", "sxy", "syz", "szx"})
      o << "variable S0" << v << " equal ${" << v << "}\n";
    for (std::size_t k = 0; k < s.unload_at.size(); ++k)
      o << "variable fired" << index << "_" << k + 1 << " equal 0\n";
  }
  o << kinematic_and_servo_variables(s, 1.0, in);
  std::string stop = "0";
  for (const Condition &c : s.stop_any)
    stop += "||" + condition_expression(c, where + "/stop when", in.case_file);
  const double chunk = double(steps_per_sample) * dt;
  const long long chunks = std::max<long long>(1, (long long)std::ceil(s.max_duration / chunk - 1e-9));
  o << "variable stop" << index << " equal " << stop << "\n"
    << "variable chunk" << index << " loop " << chunks << "\n"
    << "label loop" << index << "\n"
    << "run " << steps_per_sample << "\n"
    << "print \"" << sample_columns().second << "\" append samples.txt screen no\n"
    << keep_forces();
  for (std::size_t k = 0; k < s.unload_at.size(); ++k)
    o << trigger_block(s, index, int(k), in);
  o << "if \"${stop" << index << "} > 0\" then \"jump SELF end" << index << "\"\n"
    << "next chunk" << index << "\njump SELF loop" << index << "\n"
    << "print \"stage " << index << " reached its max duration (" << num(s.max_duration) << " s)\"\n"
    << "print \"" << index - 1 << " max-duration\" append stages.txt screen no\n"
    << "jump SELF done" << index << "\n"
    << "label end" << index << "\n"
    << "print \"" << index - 1 << " stop\" append stages.txt screen no\n"
    << "label done" << index << "\n";
  for (int a = 0; a < 3; ++a)
    if (!s.kinematic(a))
      o << "unfix I" << kAxis[a] << "\n";
  return o.str();
}

std::string header_section(const LiggghtsDeckInput &in, const std::string &restart)
{
  std::ostringstream o;
  o << "# LIGGGHTS 3.8 deck written by `geocomp export liggghts " << in.case_file << "` (docs/liggghts.md).\n"
    << "# SI units. Atom type 1: spheres; type 2: the six wall meshes. Stresses tension positive.\n";
  if (restart.empty())
    o << "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\n"
      << "communicate single vel yes\nunits si\nread_data specimen.data\n";
  else // the restart file keeps the atom style, boundary, box, atoms and the meshes' state
    o << "atom_modify map array\nnewton off\ncommunicate single vel yes\nunits si\nread_restart " << restart << "\n";
  o
    << "neighbor " << num(in.skin) << " bin\nneigh_modify delay 0\n";
  for (const std::string &line : in.contact.properties)
    o << line << "\n";
  const std::string model = "model " + in.contact.model + " tangential history";
  o << "pair_style gran " << model << " " << in.contact.options << "\npair_coeff * *\n"
    << "timestep " << num(in.time_step) << "\n";
  const Packing &p = *in.packing;
  const Eigen::Vector3d centre = 0.5 * (p.box_min + p.box_max);
  for (int w = 0; w < 6; ++w) {
    Eigen::Vector3d ref = centre;
    ref[w / 2] = w % 2 ? p.box_max[w / 2] : p.box_min[w / 2];
    o << "fix w_" << kWall[w] << " all mesh/surface/stress file wall_" << kWall[w] << ".stl type 2 reference_point "
      << num(ref[0]) << " " << num(ref[1]) << " " << num(ref[2]) << "\n";
  }
  o << "fix walls all wall/gran " << model << " mesh n_meshes 6 meshes w_xlo w_xhi w_ylo w_yhi w_zlo w_zhi "
    << in.contact.options << "\nfix integrate all nve/sphere\n";
  return o.str();
}

std::string wall_motion_section(long long steps_per_sample)
{
  std::ostringstream o;
  o << "# ---- wall motion: outward speed v<axis> of both walls, redefined by each stage\n"
       "variable vx equal 0.0\nvariable vy equal 0.0\nvariable vz equal 0.0\n"
       "variable mvx equal -v_vx\nvariable mvy equal -v_vy\nvariable mvz equal -v_vz\n"
       "fix m_xlo all move/mesh mesh w_xlo linear/variable v_mvx v_zero v_zero\n"
       "fix m_xhi all move/mesh mesh w_xhi linear/variable v_vx v_zero v_zero\n"
       "fix m_ylo all move/mesh mesh w_ylo linear/variable v_zero v_mvy v_zero\n"
       "fix m_yhi all move/mesh mesh w_yhi linear/variable v_zero v_vy v_zero\n"
       "fix m_zlo all move/mesh mesh w_zlo linear/variable v_zero v_zero v_mvz\n"
       "fix m_zhi all move/mesh mesh w_zhi linear/variable v_zero v_zero v_vz\n"
       "compute erot all erotate/sphere\nvariable ke equal ke\nvariable erot equal c_erot\n";
  for (int w = 0; w < 6; ++w)
    for (int a = 0; a < 3; ++a)
      o << "variable F" << kAxis[a] << "_" << kWall[w] << " equal f_w_" << kWall[w] << "[" << a + 1 << "]\n";
  o << "thermo_style custom step v_t v_Lx v_Ly v_Lz v_sx v_sy v_sz ke c_erot\nthermo " << steps_per_sample
    << "\nthermo_modify norm no lost error\n";
  return o.str();
}

namespace {
std::string program_start_section()
{
  std::ostringstream o;
  const auto [cols, vals] = sample_columns();
  // One row at the start of the program and one after each chunk (print, not fix print:
  // the first row is the state the program starts from, and each row carries its stage).
  o << "# One step at rest before the program: LIGGGHTS computes no wall force in a run's setup,\n"
       "# so the program starts (t = 0, the first sample) when the walls' forces exist.\n"
    << "variable stage equal 0\nvariable branch equal 0\nvariable nbranch equal 0\nvariable nrun equal 0\n";
  for (int w = 0; w < 6; ++w)
    o << "variable kF_" << kWall[w] << " equal 0.0\n";
  o << "run 1\n" << keep_forces()
    << "print \"# " << cols << "\" file samples.txt screen no\n"
    << "print \"" << vals << "\" append samples.txt screen no\n"
    << "print \"# stage end\" file stages.txt screen no\n"
    << "print \"# start id stage trigger t | end id target|max-duration\" file branches.txt screen no\n";
  return o.str();
}
} // namespace

} // namespace deck

using namespace deck;

void write_liggghts_data(const fs::path &file, const Packing &p)
{
  std::ostringstream o;
  o.precision(17);
  o << "geocomp specimen N=" << p.size() << " (atom_style granular: id type diameter density x y z)\n\n"
    << p.size() << " atoms\n2 atom types\n\n";
  const Eigen::Vector3d L = p.box_max - p.box_min;
  for (int a = 0; a < 3; ++a)
    o << p.box_min[a] - 0.5 * L[a] << " " << p.box_max[a] + 0.5 * L[a] << " " << kAxis[a] << "lo " << kAxis[a]
      << "hi\n";
  o << "\nAtoms\n\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    o << i + 1 << " 1 " << 2.0 * p.radius[i] << " " << p.density << " " << p.position[i][0] << " "
      << p.position[i][1] << " " << p.position[i][2] << "\n";
  if (!p.velocity.empty()) {
    o << "\nVelocities\n\n";
    for (std::size_t i = 0; i < p.size(); ++i)
      o << i + 1 << " " << p.velocity[i][0] << " " << p.velocity[i][1] << " " << p.velocity[i][2] << " "
        << p.angular_velocity[i][0] << " " << p.angular_velocity[i][1] << " " << p.angular_velocity[i][2] << "\n";
  }
  write_text(file, o.str());
}

void check_liggghts_program(const LoadingProgram &program, const std::string &case_file)
{
  for (std::size_t k = 0; k < program.stages.size(); ++k) {
    const Stage &s = program.stages[k];
    const std::string where = "program/stage " + std::to_string(k + 1);
    for (const Condition &c : s.stop_any)
      condition_expression(c, where + "/stop when", case_file);
    for (const BranchTrigger &b : s.unload_at) {
      if (b.kind == BranchTrigger::Kind::AtPeak)
        throw CaseError(case_file, where + "/unload at",
                        "'peak': the LIGGGHTS deck writes a restart file when a trigger holds, and a peak is "
                        "known only after it (geocomp keeps the state at every new peak); give a condition "
                        "such as 'gamma_max >= 0.02'");
      condition_expression(b.condition, where + "/unload at", case_file);
    }
    if (s.locate_elastic_limit)
      throw CaseError(case_file, where + "/locate elastic limit",
                      "the LIGGGHTS deck does not bisect the elastic limit (extra branches placed after the main "
                      "path need a restart file at every sample); set it to false and place the branches with "
                      "'unload at'");
  }
}

namespace {
LiggghtsDeckSummary write_deck_files(const fs::path &dir, const LiggghtsDeckInput &in, LiggghtsDeckSummary out);
} // namespace

LiggghtsDeckSummary write_liggghts_case(const fs::path &dir, const LiggghtsDeckInput &in)
{
  const LoadingProgram &prog = *in.program;
  LiggghtsDeckSummary out;
  // Whole steps per sample, dt at most geocomp's: the samples land on geocomp's sample times.
  out.steps_per_sample = std::max<long long>(1, (long long)std::ceil(prog.sample_interval / in.time_step - 1e-9));
  LiggghtsDeckInput timed = in;
  timed.time_step = prog.sample_interval > 0.0 ? prog.sample_interval / double(out.steps_per_sample) : in.time_step;
  out.time_step = timed.time_step;
  return write_deck_files(dir, timed, out);
}

namespace {
LiggghtsDeckSummary write_deck_files(const fs::path &dir, const LiggghtsDeckInput &in, LiggghtsDeckSummary out)
{
  const LoadingProgram &prog = *in.program;
  std::string deck = header_section(in, "") + geometry_section(*in.packing, in.contact) +
                     wall_motion_section(out.steps_per_sample) + program_start_section();
  check_liggghts_program(prog, in.case_file); // every refusal before any file is written
  std::vector<std::pair<std::string, std::string>> branches; // file, deck
  for (std::size_t k = 0; k < prog.stages.size(); ++k) {
    const Stage &s = prog.stages[k];
    deck += stage_section(s, int(k + 1), out.steps_per_sample, in.time_step, in);
    for (std::size_t b = 0; b < s.unload_at.size(); ++b) {
      const std::string name = branch_name(int(k + 1), int(b + 1));
      branches.emplace_back("in." + name, branch_deck(s, int(k + 1), int(b + 1), out.steps_per_sample, in));
      out.branch_decks.push_back(dir / ("in." + name));
    }
  }
  deck += "print \"geocomp deck: program done at t = ${t} s\"\n";
  fs::create_directories(dir);
  out.data = dir / "specimen.data";
  out.deck = dir / "in.geocomp";
  write_liggghts_data(out.data, *in.packing);
  for (int w = 0; w < 6; ++w)
    write_text(dir / ("wall_" + std::string(kWall[w]) + ".stl"), face_stl(*in.packing, w));
  write_text(out.deck, deck);
  for (const auto &[file, text] : branches)
    write_text(dir / file, text);
  return out;
}
} // namespace

} // namespace geocomp::dem

// @sect3{The deck of one unloading branch: restart at the trigger, every rate reversed}
//
// Why it exists: geocomp's ProgramRunner plays an unloading branch (S0 Fig. 2) by saving
// the engine at the trigger, running the stage with every rate reversed (StageControl
// direction -1) until tau_max is back to its level at the stage start (or `unload to`),
// and restoring the saved state for the main path. LIGGGHTS cannot save and restore a
// state inside one run, so the main deck writes a restart file at the trigger
// (`write_restart branch_<stage>_<trigger>.restart`, LiggghtsDeck.cpp) and goes on; this
// deck is a second LIGGGHTS run that reads it, declares again what a LIGGGHTS restart
// file does not hold (contact law, property fixes, wall meshes and their fixes, the box
// variables), reads the trigger's state that the main run printed beside it (the branch
// id, the origin's time, strains and stress, the stage start's stress, the walls' forces
// for the first step's servo) and plays the branch:
//  - kinematic axes: StageControl::strain with direction -1 from the origin, the stress
//    axes kept by the same servo (its integral cleared, as geocomp's begin_control does);
//  - the unloading measure is geocomp's: tau_max projected on the deviator the branch
//    leaves with, $\tau_D(\sigma) = \tau_o\,\sigma:d/(d:d)$, $d = \mathrm{dev}\,\sigma_o$
//    ($\sigma:d = \mathrm{dev}\,\sigma:d$ as $d$ is traceless), and the target is
//    $\tau_D(\sigma_{stage\ start})$ or `unload to tau`;
//  - the branch samples every interval; when the last two samples' slope puts the target
//    within the next interval, the next run is shortened to the predicted step (a secant
//    in whole steps, rounded up: the sample lands at or past the target, never short of it,
//    as geocomp's false-position landing does; LIGGGHTS has no state to restore and retry);
//  - it ends at the target (tau_D <= target + 1e-9 max(1, tau_o)) or at the stage's max
//    duration from the origin, and appends `end <id> target|max-duration` to branches.txt.
// Its rows go into samples.txt with the branch id in the `branch` column.
#include "dem/liggghts/LiggghtsDeckParts.h"

#include <sstream>

namespace geocomp::dem::deck {

namespace {
/// tau_D and the target: the deviator d of the origin's stress O (from the state file).
std::string unloading_measure(const Stage &s)
{
  std::ostringstream o;
  o << "variable Om equal (v_Osx+v_Osy+v_Osz)/3\n"
       "variable dxx equal v_Osx-v_Om\nvariable dyy equal v_Osy-v_Om\nvariable dzz equal v_Osz-v_Om\n"
       "variable dd equal v_dxx^2+v_dyy^2+v_dzz^2+2*(v_Osxy^2+v_Osyz^2+v_Oszx^2)\n";
  auto along = [](const std::string &p) { // tau_D of the stress whose components are v_<p>sx...
    return "v_taustart*(v_" + p + "sx*v_dxx+v_" + p + "sy*v_dyy+v_" + p + "sz*v_dzz+2*(v_" + p + "sxy*v_Osxy+v_" + p +
           "syz*v_Osyz+v_" + p + "szx*v_Oszx))/(v_dd+(v_dd<=0))";
  };
  // An isotropic origin (d = 0) has no deviator to follow: tau_max itself, as geocomp.
  o << "variable along equal (v_dd>0)*" << along("") << "+(v_dd<=0)*v_tau_max\n";
  if (s.unload_to_start)
    o << "variable target equal (v_dd>0)*" << along("S") << "\n";
  else
    o << "variable target equal " << num(s.unload_to_tau) << "\n";
  o << "variable tol equal 1e-9*(1+(abs(v_taustart)-1)*(abs(v_taustart)>1))\n"
       "variable reached equal v_along<=v_target+v_tol\n";
  return o.str();
}
} // namespace

std::string branch_deck(const Stage &s, int stage, int trigger, long long steps_per_sample,
                        const LiggghtsDeckInput &in)
{
  const std::string name = branch_name(stage, trigger);
  const std::string S = std::to_string(steps_per_sample);
  std::ostringstream o;
  o << header_section(in, name + ".restart") << geometry_section(*in.packing, in.contact)
    << wall_motion_section(steps_per_sample) << "# ---- unloading branch from stage " << stage << ", trigger "
    << trigger << " ('" << s.unload_at[trigger - 1].text << "'): every rate reversed\n"
    << "variable stage equal " << stage - 1 << "\ninclude " << name << ".state\n"
    << "variable n0 equal ${nowstep}\n"
    << kinematic_and_servo_variables(s, -1.0, in) << unloading_measure(s)
    << "variable tend equal v_t0+" << num(s.max_duration) << "\n"
    << "variable late equal v_t>=v_tend-0.5*v_dt\n"
    // the next run's steps: a whole interval, or the secant's step to the target, at least 1
    << "variable slope equal (v_aprev-v_anow)/v_nlast\n"
    << "variable npred equal ceil((v_anow-v_target)/(v_slope+(v_slope<=0)*1e300))\n"
    << "variable nfull equal (v_slope<=0)*" << S << "+(v_slope>0)*(" << S << "-(" << S
    << "-v_npred)*(v_npred<" << S << "))\n"
    << "variable nleft equal floor((v_tend-v_t)/v_dt+0.5)\n"
    << "variable nn equal v_nfull-(v_nfull-v_nleft)*(v_nleft<v_nfull)\n"
    << "variable nnext equal " << S << "\nvariable aprev equal ${taustart}\n"
    << "label bloop\nrun ${nnext}\n"
    << "print \"" << sample_columns().second << "\" append samples.txt screen no\n"
    << keep_forces() << "if \"${reached} > 0\" then \"jump SELF reached\"\n"
    << "if \"${late} > 0\" then \"jump SELF late\"\n"
    << "variable anow equal ${along}\nvariable nlast equal ${nnext}\n"
    << "variable nnext equal ${nn}\n"
    << "if \"${nnext} < 1\" then \"variable nnext equal 1\"\n"
    << "variable aprev equal ${anow}\njump SELF bloop\n"
    << "label late\nprint \"branch ${branch} reached the stage's max duration (" << num(s.max_duration)
    << " s) before its target\"\n"
    << "print \"end ${branch} max-duration\" append branches.txt screen no\njump SELF done\n"
    << "label reached\nprint \"end ${branch} target\" append branches.txt screen no\n"
    << "label done\nprint \"geocomp deck: branch ${branch} done at t = ${t} s\"\n";
  return o.str();
}

} // namespace geocomp::dem::deck

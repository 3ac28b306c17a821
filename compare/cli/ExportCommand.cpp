// `geocomp export`: a stored specimen to another tool's packing file (xyzr text or a
// LAMMPS/LIGGGHTS data file), the list of a store's specimens, or a whole case as a
// LIGGGHTS run (`export liggghts <case> --output DIR`, LiggghtsExport.cpp).
#include "Commands.h"
#include "LiggghtsExport.h"

#include "common/case/CaseParameters.h"
#include "dem/program/SpecimenExchange.h"
#include "dem/program/SpecimenStore.h"
#include "dem/specimen/Packing.h"

#include <filesystem>
#include <iostream>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {

void list_store(const fs::path &store)
{
  for (const std::string &name : dem::stored_specimen_names(store)) {
    const dem::StoredSpecimen s = dem::read_stored_specimen(store, name);
    std::cout << name << ": N = " << s.metadata.particles << ", eta = " << s.record.final_packing_fraction
              << " (target " << s.metadata.packing_fraction << "), sigma_0 = " << s.metadata.isotropic_pressure
              << " Pa, mu_s = " << s.metadata.contact.particle_friction << ", seed " << s.metadata.seed << "\n";
  }
}

} // namespace

Command export_command()
{
  Command c;
  c.name = "export";
  c.summary = "write a stored specimen as an xyzr text or LAMMPS/LIGGGHTS data file, list a store, "
              "or write a case as a LIGGGHTS run";
  c.usage =
    "usage: geocomp export <store.h5>                 list the specimens of a core store\n"
    "       geocomp export <store.h5> <name> <file>   write specimen <name> to <file>\n"
    "       geocomp export liggghts <case> --output DIR   the case as a LIGGGHTS 3.8 run\n\n"
    "The format follows the extension: '.data' writes a LAMMPS/LIGGGHTS data file (atom_style\n"
    "granular: id type diameter density x y z), anything else 'x y z r' per line with the box\n"
    "in a '#' header line (../shared/bench/data/*.xyzr). The box is the box of the specimen's six\n"
    "walls; positions and radii carry 17 significant digits. Either file is read back by a case\n"
    "with `specimen/source = text`. Velocities and contact histories are not exported: use the\n"
    "store itself for an exact restart. The file is written under a temporary name and renamed.\n\n"
    + liggghts_export_usage() +
    "\nExit codes: 0 done, 2 bad input (store, name, output file, a case entry LIGGGHTS cannot\n"
    "play), 1 the write failed.\n";
  c.run = [](const std::vector<std::string> &args) {
    if (!args.empty() && args[0] == "liggghts")
      return export_liggghts(std::vector<std::string>(args.begin() + 1, args.end()));
    const Arguments a = Arguments::parse(args, {}, {});
    if (a.positional.size() != 1 && a.positional.size() != 3)
      throw UsageError("expected a store, or a store, a specimen name and an output file");
    const fs::path store = a.positional[0];
    if (!fs::exists(store))
      throw CaseError(store.string(), "store", "no such file: expected a core store written by `geocomp pack`");
    try {
      if (a.positional.size() == 1) {
        list_store(store);
        return static_cast<int>(ok);
      }
      const std::string &name = a.positional[1];
      const fs::path out = a.positional[2];
      if (out.has_parent_path() && !fs::is_directory(out.parent_path()))
        throw CaseError(out.string(), "output file", "its folder does not exist");
      const dem::StoredSpecimen s = dem::read_stored_specimen(store, name);
      const dem::Packing p = dem::packing_of(s.system, s.metadata.density);
      dem::write_packing_file(out, p);
      std::cout << "export: '" << name << "' (" << p.size() << " spheres, box " << (p.box_max - p.box_min).transpose()
                << " m, packing fraction " << p.packing_fraction() << ") -> " << out.string()
                << (dem::is_lammps_data_file(out) ? " (LAMMPS data)" : " (x y z r)") << "\n";
    } catch (const dem::StoreError &e) {
      throw CaseError(store.string(), e.missing_name ? "name" : "store", e.what());
    }
    return static_cast<int>(ok);
  };
  return c;
}

} // namespace geocomp::cli

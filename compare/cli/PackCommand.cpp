// `geocomp pack`: builds a case's specimen (S0 radius growth + consolidation) into a core store.
#include "CaseValidation.h"
#include "Log.h"
#include "Commands.h"
#include "OutputFolderLock.h"
#include "Progress.h"

#include "compare/case/CaseDescription.h"
#include "dem/program/SpecimenPreparation.h"
#include "dem/program/SpecimenStore.h"

#include <sstream>
#include <filesystem>
#include <iostream>

namespace geocomp::cli {

namespace fs = std::filesystem;

Command pack_command()
{
  Command c;
  c.name = "pack";
  c.summary = "prepare a case's DEM specimen (S0 radius growth, consolidation) into a core store";
  c.usage =
    "usage: geocomp pack <case.prm|case.json> [--store FILE] [--name NAME]\n\n"
    "Prepares the specimen of the case's `specimen`, `contact` and `dem` sections (source =\n"
    "generate: random placement, radius growth to the packing fraction, friction on, rest,\n"
    "isotropic consolidation to sigma_0; source = text: the file's spheres) and adds it to\n"
    "the core store (HDF5), replacing a specimen of the same name. The store is written\n"
    "under a temporary name and renamed. A case then uses it with\n"
    "  set source = store, set store file = FILE, set store name = NAME.\n\n"
    "  --store FILE  the store (default: the case's `specimen/store file`)\n"
    "  --name NAME   the specimen's name (default: `specimen/store name`, else the case file's\n"
    "                name without extension)\n\n"
    "Exit codes: 0 done, 2 bad input (case file, store, name), 1 the preparation failed.\n";
  c.run = [](const std::vector<std::string> &args) {
    const Arguments a = Arguments::parse(args, {"store", "name"}, {});
    if (a.positional.size() != 1)
      throw UsageError("expected exactly one case file");
    // CaseError -> exit 2 in main; a store source is refused below, before it is validated.
    const CaseDescription d = read_case(a.positional[0]);
    if (d.specimen.source == "store")
      throw CaseError(d.file, "specimen/source",
                      "pack prepares a specimen: expected generate or text, not store (the store is where it goes)");
    validate_engines(d, {"dem"});
    const fs::path store = a.has("store") ? fs::path(a.get("store")) : fs::path(d.specimen.store_file);
    if (store.empty())
      throw CaseError(d.file, "specimen/store file", "no store to pack into: set it or pass --store FILE");
    std::string name = a.has("name") ? a.get("name") : d.specimen.store_name;
    if (name.empty())
      name = fs::path(d.file).stem().string();
    if (!dem::valid_specimen_name(name))
      throw CaseError(d.file, "specimen/store name",
                      "'" + name + "' is not a specimen name (letters, digits, '_', '-', '.')");
    // One writer per store folder at a time: two packs into one store would each rename their
    // copy over the other's, and one specimen would be lost.
    const fs::path folder = store.has_parent_path() ? store.parent_path() : fs::path(".");
    const OutputFolderLock lock(folder, d.file,
                                a.has("store") ? "--store" : "specimen/store file");
    if (fs::exists(store)) {
      try {
        dem::stored_specimen_names(store); // refuse to overwrite a file that is not a store
      } catch (const dem::StoreError &e) {
        throw CaseError(d.file, "specimen/store file", e.what());
      }
    }
    std::ostringstream what;
    what << "pack: " << d.specimen.particles << " spheres, eta = " << d.specimen.packing_fraction
         << ", sigma_0 = " << d.specimen.isotropic_pressure << " Pa"
         << (d.specimen.aristotelian ? " (Aristotelian growth)" : "") << " -> " << store.string() << " : " << name;
    log::info(what.str());
    PhasePrinter phases("pack");
    dem::PreparedSpecimen s = dem::prepare_specimen(d, {}, std::ref(phases));
    phases.finish();
    log::info("pack: " + s.record.describe());
    try {
      dem::write_stored_specimen(store, name, s, dem::SpecimenMetadata::from_case(d, s));
    } catch (const dem::StoreError &e) {
      throw CaseError(d.file, "specimen/store file", e.what());
    }
    log::info("pack: stored '" + name + "' in " + store.string());
    return static_cast<int>(ok);
  };
  return c;
}

} // namespace geocomp::cli

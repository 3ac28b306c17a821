#include "common/ResponseFile.h"

#include "common/AtomicFile.h"
#include "common/Hdf5.h"
#include "common/Version.h"

#include <ctime>

namespace geocomp {

namespace {
std::vector<double> tensors(const Response &r, Tensor3 (*f)(const ResponseSample &))
{
  std::vector<double> out;
  out.reserve(9 * r.samples.size());
  for (const auto &s : r.samples) {
    const Tensor3 t = f(s);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        out.push_back(t(i, j));
  }
  return out;
}
std::vector<double> scalars(const Response &r, double (*f)(const ResponseSample &))
{
  std::vector<double> out;
  out.reserve(r.samples.size());
  for (const auto &s : r.samples)
    out.push_back(f(s));
  return out;
}
std::string now_iso()
{
  std::time_t t = std::time(nullptr);
  char buf[64];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}
} // namespace

void write_response(const std::filesystem::path &path, const Response &r, RunMeta meta)
{
  if (meta.version.empty())
    meta.version = GEOCOMP_VERSION;
  if (meta.git_hash.empty())
    meta.git_hash = GEOCOMP_GIT_HASH;
  write_atomically(path, [&](const std::filesystem::path &tmp) {
    h5::Handle file = h5::create_file(tmp);
    {
      h5::Handle m = h5::create_group(file.id(), "meta");
      h5::write_attribute(m.id(), "engine", r.engine);
      h5::write_attribute(m.id(), "version", meta.version);
      h5::write_attribute(m.id(), "git_hash", meta.git_hash);
      h5::write_attribute(m.id(), "seed", static_cast<long long>(meta.seed));
      h5::write_attribute(m.id(), "case_file", meta.case_file);
      h5::write_attribute(m.id(), "command", meta.command);
      h5::write_attribute(m.id(), "created", now_iso());
      h5::write_attribute(m.id(), "sign_convention", std::string("tension positive (stress and strain)"));
      h5::write_attribute(m.id(), "units", std::string("SI: s, m, Pa, N"));
      if (!meta.kinematics.empty())
        h5::write_attribute(m.id(), "kinematics", meta.kinematics);
      h5::write(m.id(), "case_text", std::vector<std::string>{meta.case_text});
      h5::write(m.id(), "status", std::vector<std::string>{meta.status});
      if (!meta.parameters.empty())
        h5::write(m.id(), "parameters", std::vector<std::string>{meta.parameters});
      if (!meta.specimen_record.empty())
        h5::write(m.id(), "specimen_record", std::vector<std::string>{meta.specimen_record});
    }
    const hsize_t n = r.samples.size();
    h5::Handle g = h5::create_group(file.id(), "response");
    h5::write(g.id(), "time", scalars(r, [](const ResponseSample &s) { return s.time; }), {n}, "s");
    h5::write(g.id(), "strain", tensors(r, [](const ResponseSample &s) -> Tensor3 { return s.strain; }),
              {n, 3, 3}, "1");
    h5::write(g.id(), "log_strain",
              tensors(r, [](const ResponseSample &s) -> Tensor3 { return logarithmic_strain(s.strain); }),
              {n, 3, 3}, "1");
    h5::write(g.id(), "stress", tensors(r, [](const ResponseSample &s) -> Tensor3 { return s.stress; }),
              {n, 3, 3}, "Pa");
    h5::write(g.id(), "stress_mean", tensors(r, [](const ResponseSample &s) -> Tensor3 { return s.stress_mean; }),
              {n, 3, 3}, "Pa");
    {
      h5::Handle set(H5Dopen2(g.id(), "stress_mean", H5P_DEFAULT), H5Dclose);
      const char *what = r.interval_means ? "mean of the stress over the sampling interval ending at the sample"
                                          : "the instantaneous stress (the engine gives no interval mean)";
      h5::write_attribute(set.id(), "description", std::string(what));
    }
    h5::write(g.id(), "volumetric_strain",
              scalars(r, [](const ResponseSample &s) { return volumetric_strain(s.strain); }), {n}, "1");
    h5::write(g.id(), "gamma_max", scalars(r, [](const ResponseSample &s) { return gamma_max(s.strain); }),
              {n}, "1");
    h5::write(g.id(), "tau_max", scalars(r, [](const ResponseSample &s) { return tau_max(s.stress); }), {n},
              "Pa");
    h5::write(g.id(), "mean_stress", scalars(r, [](const ResponseSample &s) { return mean_stress(s.stress); }),
              {n}, "Pa");
    std::vector<int> stage, branch;
    for (const auto &s : r.samples) {
      stage.push_back(s.stage);
      branch.push_back(s.branch);
    }
    h5::write(g.id(), "stage", stage);
    h5::write(g.id(), "branch", branch);
    {
      h5::Handle x = h5::create_group(g.id(), "extras");
      for (std::size_t k = 0; k < r.extras.size(); ++k) {
        std::vector<double> col;
        col.reserve(n);
        for (const auto &s : r.samples)
          col.push_back(k < s.extras.size() ? s.extras[k] : 0.0);
        h5::write(x.id(), r.extras[k].name, col, {n}, r.extras[k].units.empty() ? "1" : r.extras[k].units);
        h5::Handle set(H5Dopen2(x.id(), r.extras[k].name.c_str(), H5P_DEFAULT), H5Dclose);
        h5::write_attribute(set.id(), "description", r.extras[k].description);
      }
    }
    {
      h5::Handle st = h5::create_group(file.id(), "stages");
      h5::write(st.id(), "name", r.stage_names);
      h5::write(st.id(), "end_reason", r.stage_end_reasons);
    }
    {
      h5::Handle b = h5::create_group(file.id(), "branches");
      std::vector<int> id, stage_of;
      std::vector<long long> first, last;
      std::vector<double> tau_start, tau_target, gamma_start, residual;
      std::vector<int> reached;
      std::vector<std::string> trigger;
      for (const auto &br : r.branches) {
        id.push_back(br.id);
        stage_of.push_back(br.stage);
        first.push_back(static_cast<long long>(br.first_sample));
        last.push_back(static_cast<long long>(br.last_sample));
        tau_start.push_back(br.tau_start);
        tau_target.push_back(br.tau_target);
        gamma_start.push_back(br.gamma_start);
        residual.push_back(br.residual_gamma);
        reached.push_back(br.reached_target ? 1 : 0);
        trigger.push_back(br.trigger);
      }
      const hsize_t m = r.branches.size();
      h5::write(b.id(), "id", id);
      h5::write(b.id(), "stage", stage_of);
      h5::write(b.id(), "trigger", trigger);
      h5::write(b.id(), "first_sample", first);
      h5::write(b.id(), "last_sample", last);
      h5::write(b.id(), "tau_start", tau_start, {m}, "Pa");
      h5::write(b.id(), "tau_target", tau_target, {m}, "Pa");
      h5::write(b.id(), "gamma_start", gamma_start, {m}, "1");
      h5::write(b.id(), "residual_gamma", residual, {m}, "1");
      h5::write(b.id(), "reached_target", reached);
    }
  });
}

Response read_response(const std::filesystem::path &path, RunMeta *meta)
{
  h5::Handle file = h5::open_file(path);
  Response r;
  {
    h5::Handle m = h5::open_group(file.id(), "meta");
    r.engine = h5::read_string_attribute(m.id(), "engine");
    if (meta) {
      meta->version = h5::read_string_attribute(m.id(), "version");
      meta->git_hash = h5::read_string_attribute(m.id(), "git_hash");
      meta->seed = static_cast<unsigned long long>(h5::read_int_attribute(m.id(), "seed"));
      meta->case_file = h5::read_string_attribute(m.id(), "case_file");
      meta->command = h5::read_string_attribute(m.id(), "command");
      if (h5::has_attribute(m.id(), "kinematics"))
        meta->kinematics = h5::read_string_attribute(m.id(), "kinematics");
      const auto text = h5::read_strings(m.id(), "case_text");
      meta->case_text = text.empty() ? "" : text.front();
      const auto status =
        h5::exists(m.id(), "status") ? h5::read_strings(m.id(), "status") : std::vector<std::string>{};
      meta->status = status.empty() ? "complete" : status.front();
      for (auto [name, field] : {std::pair{"parameters", &RunMeta::parameters},
                                 std::pair{"specimen_record", &RunMeta::specimen_record}}) {
        const auto text = h5::exists(m.id(), name) ? h5::read_strings(m.id(), name) : std::vector<std::string>{};
        meta->*field = text.empty() ? "" : text.front();
      }
    }
  }
  h5::Handle g = h5::open_group(file.id(), "response");
  const auto time = h5::read_doubles(g.id(), "time");
  const auto strain = h5::read_doubles(g.id(), "strain");
  const auto stress = h5::read_doubles(g.id(), "stress");
  // Files written before the interval means: the mean is the instantaneous stress.
  const bool has_mean = h5::exists(g.id(), "stress_mean");
  const auto stress_mean = has_mean ? h5::read_doubles(g.id(), "stress_mean") : stress;
  if (has_mean) {
    h5::Handle set(H5Dopen2(g.id(), "stress_mean", H5P_DEFAULT), H5Dclose);
    r.interval_means = h5::has_attribute(set.id(), "description") &&
                       h5::read_string_attribute(set.id(), "description").rfind("mean", 0) == 0;
  }
  const auto stage = h5::read_ints(g.id(), "stage");
  const auto branch = h5::read_ints(g.id(), "branch");
  const std::size_t n = time.size();
  if (strain.size() != 9 * n || stress.size() != 9 * n || stress_mean.size() != 9 * n || stage.size() != n ||
      branch.size() != n)
    throw h5::Error("inconsistent /response datasets in " + path.string());
  r.samples.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    auto &s = r.samples[k];
    s.time = time[k];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        s.strain(i, j) = strain[9 * k + 3 * i + j];
        s.stress(i, j) = stress[9 * k + 3 * i + j];
        s.stress_mean(i, j) = stress_mean[9 * k + 3 * i + j];
      }
    s.stage = stage[k];
    s.branch = branch[k];
  }
  {
    h5::Handle x = h5::open_group(g.id(), "extras");
    for (const auto &name : h5::list(x.id())) {
      h5::Handle set(H5Dopen2(x.id(), name.c_str(), H5P_DEFAULT), H5Dclose);
      ExtraColumn c{name, h5::read_string_attribute(set.id(), "units"),
                    h5::read_string_attribute(set.id(), "description")};
      r.extras.push_back(c);
      const auto col = h5::read_doubles(x.id(), name);
      for (std::size_t k = 0; k < n && k < col.size(); ++k)
        r.samples[k].extras.push_back(col[k]);
    }
  }
  {
    h5::Handle st = h5::open_group(file.id(), "stages");
    r.stage_names = h5::read_strings(st.id(), "name");
    r.stage_end_reasons = h5::read_strings(st.id(), "end_reason");
  }
  {
    h5::Handle b = h5::open_group(file.id(), "branches");
    const auto id = h5::read_ints(b.id(), "id");
    const auto stage_of = h5::read_ints(b.id(), "stage");
    const auto trigger = h5::read_strings(b.id(), "trigger");
    const auto first = h5::read_int64s(b.id(), "first_sample");
    const auto last = h5::read_int64s(b.id(), "last_sample");
    const auto tau_start = h5::read_doubles(b.id(), "tau_start");
    const auto tau_target = h5::read_doubles(b.id(), "tau_target");
    const auto gamma_start = h5::read_doubles(b.id(), "gamma_start");
    const auto residual = h5::read_doubles(b.id(), "residual_gamma");
    const auto reached = h5::read_ints(b.id(), "reached_target");
    for (std::size_t k = 0; k < id.size(); ++k) {
      BranchRecord br;
      br.id = id[k];
      br.stage = stage_of[k];
      br.trigger = trigger[k];
      br.first_sample = static_cast<std::size_t>(first[k]);
      br.last_sample = static_cast<std::size_t>(last[k]);
      br.tau_start = tau_start[k];
      br.tau_target = tau_target[k];
      br.gamma_start = gamma_start[k];
      br.residual_gamma = residual[k];
      br.reached_target = reached[k] != 0;
      r.branches.push_back(br);
    }
  }
  return r;
}

} // namespace geocomp

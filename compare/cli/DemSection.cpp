#include "DemSection.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace geocomp::cli {

namespace fs = std::filesystem;

namespace {
const char *const section_file = "dem-midplane.bin";
const char magic[8] = {'G', 'C', 'S', 'E', 'C', 'T', '0', '1'};

template <class T> void put(std::ostream &out, const T &v) { out.write(reinterpret_cast<const char *>(&v), sizeof v); }
template <class T> T get(std::istream &in)
{
  T v{};
  in.read(reinterpret_cast<char *>(&v), sizeof v);
  return v;
}

std::uintmax_t header_bytes(std::size_t n) { return 8 + 8 + 3 * 8 + 24 * std::uintmax_t(n); }
std::uintmax_t record_bytes(std::size_t n) { return 8 + 16 * std::uintmax_t(n); }

/// The header of a section file: particle count, box centre, mean radius, ids and reference (x, z).
struct Header {
  std::size_t n = 0;
  double centre_x = 0.0, centre_z = 0.0, mean_radius = 0.0;
  std::vector<std::int64_t> ids;
  std::vector<double> x, z;
};

/// Reads the header; false when the file has none (then `in` is useless).
bool read_header(std::istream &in, Header &h)
{
  char m[8] = {};
  in.read(m, 8);
  if (!in || std::memcmp(m, magic, 8) != 0)
    return false;
  h.n = get<std::uint64_t>(in);
  h.centre_x = get<double>(in);
  h.centre_z = get<double>(in);
  h.mean_radius = get<double>(in);
  h.ids.resize(h.n);
  h.x.resize(h.n);
  h.z.resize(h.n);
  in.read(reinterpret_cast<char *>(h.ids.data()), std::streamsize(8 * h.n));
  in.read(reinterpret_cast<char *>(h.x.data()), std::streamsize(8 * h.n));
  in.read(reinterpret_cast<char *>(h.z.data()), std::streamsize(8 * h.n));
  return bool(in);
}
} // namespace

DemSectionRecorder::DemSectionRecorder(const dem::DemEngine &engine, const CaseDescription &c, const fs::path &dir)
  : engine_(engine), file_(dir / section_file), tolerance_(0.5 * c.program.sample_interval)
{
  fs::create_directories(dir);
}

void DemSectionRecorder::start()
{
  fs::remove(file_);
  last_time_.reset();
  ids_.clear();
  slot_.clear();
}

void DemSectionRecorder::resume(double time)
{
  Header h;
  std::ifstream in(file_, std::ios::binary);
  if (!in || !read_header(in, h)) {
    in.close();
    start();
    return;
  }
  const std::uintmax_t size = fs::file_size(file_), records = (size - header_bytes(h.n)) / record_bytes(h.n);
  std::uintmax_t keep = 0;
  for (; keep < records; ++keep) {
    in.seekg(std::streamoff(header_bytes(h.n) + keep * record_bytes(h.n)));
    const double t = get<double>(in);
    if (!in || t > time + tolerance_)
      break;
    last_time_ = t;
  }
  in.close();
  fs::resize_file(file_, header_bytes(h.n) + keep * record_bytes(h.n));
  ids_ = h.ids;
  slot_.clear();
  for (std::size_t i = 0; i < ids_.size(); ++i)
    slot_[ids_[i]] = i;
  if (keep == 0)
    last_time_.reset();
}

void DemSectionRecorder::write_header(const dem::ParticleFields &f)
{
  double mean_radius = 0.0;
  for (double r : f.radii)
    mean_radius += r / double(f.radii.size());
  const double y_mid = 0.5 * (f.box_min.y() + f.box_max.y());
  std::vector<double> x, z;
  for (std::size_t i = 0; i < f.ids.size(); ++i)
    if (std::abs(f.positions[i].y() - y_mid) <= 2.0 * mean_radius) {
      slot_[f.ids[i]] = ids_.size();
      ids_.push_back(f.ids[i]);
      x.push_back(f.positions[i].x());
      z.push_back(f.positions[i].z());
    }
  std::ofstream out(file_, std::ios::binary | std::ios::trunc);
  out.write(magic, 8);
  put<std::uint64_t>(out, ids_.size());
  put(out, 0.5 * (f.box_min.x() + f.box_max.x()));
  put(out, 0.5 * (f.box_min.z() + f.box_max.z()));
  put(out, mean_radius);
  out.write(reinterpret_cast<const char *>(ids_.data()), std::streamsize(8 * ids_.size()));
  out.write(reinterpret_cast<const char *>(x.data()), std::streamsize(8 * x.size()));
  out.write(reinterpret_cast<const char *>(z.data()), std::streamsize(8 * z.size()));
  if (!out)
    throw std::runtime_error("cannot write " + file_.string());
}

// Main-path samples of the last stage only, each once: a sample not later than the last
// record (the checkpoint's own sample after a resume) is not recorded again.
void DemSectionRecorder::operator()(const RunProgress &p)
{
  if (p.branch != 0 || p.stage != p.stage_count - 1 || !p.sample)
    return;
  const double t = p.sample->time;
  if (last_time_ && t <= *last_time_ + tolerance_)
    return;
  const dem::ParticleFields f = engine_.snapshot();
  if (ids_.empty())
    write_header(f);
  std::vector<double> xz(2 * ids_.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < f.ids.size(); ++i) {
    const auto it = slot_.find(f.ids[i]);
    if (it == slot_.end())
      continue;
    xz[2 * it->second] = f.positions[i].x();
    xz[2 * it->second + 1] = f.positions[i].z();
  }
  std::ofstream out(file_, std::ios::binary | std::ios::app);
  put(out, t);
  out.write(reinterpret_cast<const char *>(xz.data()), std::streamsize(8 * xz.size()));
  if (!out)
    throw std::runtime_error("cannot write " + file_.string());
  last_time_ = t;
}

std::optional<compare::SectionSeries> read_dem_section(const fs::path &dir)
{
  const fs::path file = dir / section_file;
  std::ifstream in(file, std::ios::binary);
  Header h;
  if (!in || !read_header(in, h))
    return std::nullopt;
  compare::SectionSeries s;
  s.engine = "DEM";
  s.x = h.x;
  s.z = h.z;
  s.centre_x = h.centre_x;
  s.centre_z = h.centre_z;
  s.strain_radius = 3.0 * h.mean_radius;
  s.marker = h.mean_radius;
  const std::uintmax_t records = (fs::file_size(file) - header_bytes(h.n)) / record_bytes(h.n);
  std::vector<double> xz(2 * h.n), first;
  for (std::uintmax_t k = 0; k < records; ++k) {
    const double t = get<double>(in);
    in.read(reinterpret_cast<char *>(xz.data()), std::streamsize(8 * xz.size()));
    if (!in)
      throw std::runtime_error(file.string() + ": record " + std::to_string(k) + " cut short");
    if (k == 0)
      first = xz;
    s.times.push_back(t);
    s.ux.emplace_back(h.n);
    s.uz.emplace_back(h.n);
    for (std::size_t i = 0; i < h.n; ++i) {
      s.ux.back()[i] = xz[2 * i] - first[2 * i];
      s.uz.back()[i] = xz[2 * i + 1] - first[2 * i + 1];
    }
  }
  return s;
}

} // namespace geocomp::cli

#include "compare/ModelLadder.h"

#include "compare/HtmlString.h"
#include "compare/JsonString.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace geocomp::compare {

namespace {
std::string num(double v, int digits)
{
  if (!std::isfinite(v))
    return "null";
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::string cell(double v, int digits) { return "<td>" + (std::isfinite(v) ? num(v, digits) : "&mdash;") + "</td>"; }

double number(const nlohmann::json &j, const char *key)
{
  return j.contains(key) && j.at(key).is_number() ? j.at(key).get<double>() : nan;
}
} // namespace

double akaike(double rss, std::size_t n, std::size_t k)
{
  return double(n) * std::log(rss / double(n)) + 2.0 * double(k);
}

double bayesian(double rss, std::size_t n, std::size_t k)
{
  return double(n) * std::log(rss / double(n)) + double(k) * std::log(double(n));
}

void rank_rungs(std::vector<LadderRung> &rungs)
{
  double best_aic = nan, best_bic = nan;
  for (LadderRung &r : rungs) {
    if (!r.failure.empty() || !(r.rss > 0.0) || r.n == 0)
      continue; // an exact fit (RSS = 0) has no finite criterion
    r.aic = akaike(r.rss, r.n, r.k);
    r.bic = bayesian(r.rss, r.n, r.k);
    best_aic = std::isfinite(best_aic) ? std::min(best_aic, r.aic) : r.aic;
    best_bic = std::isfinite(best_bic) ? std::min(best_bic, r.bic) : r.bic;
  }
  for (LadderRung &r : rungs) {
    r.delta_aic = r.aic - best_aic;
    r.delta_bic = r.bic - best_bic;
  }
}

std::string ladder_html(const std::vector<LadderRung> &rungs)
{
  if (rungs.empty())
    return "";
  const bool held_out = std::any_of(rungs.begin(), rungs.end(), [](const LadderRung &r) { return std::isfinite(r.held_out_q); });
  std::ostringstream h;
  h << "<h2>Model ladder</h2>\n<p>Each model fitted to the same curves by the same least squares: k free parameters, "
       "n residuals, RSS their sum of squares (weighted, each relative to its curve's scale), rms of each quantity "
       "over all fitted samples; AIC = n ln(RSS/n) + 2k and BIC = n ln(RSS/n) + k ln n (Gaussian errors), &Delta; "
       "to the best rung: the lower, the better the residual pays for the parameters (2 or more: preferred, 10 or "
       "more: clearly)"
    << (held_out ? "; held out: the rms of the curve left out of the fit, predicted by the rung" : "")
    << ".</p>\n<table id=\"ladder\"><tr><th>model</th><th>k</th><th>n</th><th>RSS</th><th>rms q</th><th>rms p</th>"
       "<th>rms eps_v</th><th>AIC</th><th>BIC</th><th>&Delta;AIC</th><th>&Delta;BIC</th>";
  if (held_out)
    h << "<th>held out rms q</th><th>held out rms p</th><th>held out rms eps_v</th>";
  h << "<th>fitted parameters</th><th>fit [s]</th></tr>\n";
  for (const LadderRung &r : rungs) {
    h << "<tr><th>" << html_text(r.name) << "</th>";
    if (!r.failure.empty()) {
      h << "<td colspan=\"" << (held_out ? 13 : 10) << "\" style=\"text-align:left\">not fitted: "
        << html_text(r.failure) << "</td>";
    } else {
      h << "<td>" << r.k << "</td><td>" << r.n << "</td>" << cell(r.rss, 4) << cell(r.rms_q, 3) << cell(r.rms_p, 3)
        << cell(r.rms_eps_v, 3) << cell(r.aic, 6) << cell(r.bic, 6) << cell(r.delta_aic, 4) << cell(r.delta_bic, 4);
      if (held_out)
        h << cell(r.held_out_q, 3) << cell(r.held_out_p, 3) << cell(r.held_out_eps_v, 3);
    }
    std::string list;
    for (const auto &p : r.parameters)
      list += (list.empty() ? "" : ", ") + p;
    h << "<td style=\"text-align:left\">" << html_text(list) << "</td>" << cell(r.seconds, 3) << "</tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

std::string ladder_json(const std::vector<LadderRung> &rungs, const std::string &indent)
{
  std::ostringstream j;
  j << "[";
  for (std::size_t i = 0; i < rungs.size(); ++i) {
    const LadderRung &r = rungs[i];
    j << (i ? "," : "") << "\n" << indent << "  {\"model\": " << json_string(r.name) << ", \"fitted\": "
      << (r.failure.empty() ? "true" : "false");
    if (!r.failure.empty())
      j << ", \"failure\": " << json_string(r.failure);
    j << ", \"k\": " << r.k << ", \"n\": " << r.n << ", \"rss\": " << num(r.rss, 17) << ", \"rms_q\": " << num(r.rms_q, 10)
      << ", \"rms_p\": " << num(r.rms_p, 10) << ", \"rms_eps_v\": " << num(r.rms_eps_v, 10)
      << ", \"aic\": " << num(r.aic, 17) << ", \"bic\": " << num(r.bic, 17) << ", \"delta_aic\": " << num(r.delta_aic, 17)
      << ", \"delta_bic\": " << num(r.delta_bic, 17) << ", \"held_out_rms_q\": " << num(r.held_out_q, 10)
      << ", \"held_out_rms_p\": " << num(r.held_out_p, 10) << ", \"held_out_rms_eps_v\": " << num(r.held_out_eps_v, 10)
      << ", \"seconds\": " << num(r.seconds, 4) << ", \"parameters\": [";
    for (std::size_t p = 0; p < r.parameters.size(); ++p)
      j << (p ? ", " : "") << json_string(r.parameters[p]);
    j << "]}";
  }
  j << (rungs.empty() ? "]" : "\n" + indent + "]");
  return j.str();
}

std::vector<LadderRung> ladder_from_fit_json(const std::string &fit_json)
{
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(fit_json);
  } catch (const nlohmann::json::exception &e) {
    throw std::runtime_error(std::string("fit.json is not JSON: ") + e.what());
  }
  std::vector<LadderRung> rungs;
  if (!j.is_object() || !j.contains("ladder") || !j.at("ladder").is_array())
    return rungs;
  for (const auto &e : j.at("ladder")) {
    LadderRung r;
    r.name = e.value("model", std::string());
    r.failure = e.value("failure", std::string());
    r.k = e.value("k", std::size_t(0));
    r.n = e.value("n", std::size_t(0));
    r.rss = number(e, "rss");
    r.rms_q = number(e, "rms_q");
    r.rms_p = number(e, "rms_p");
    r.rms_eps_v = number(e, "rms_eps_v");
    r.aic = number(e, "aic");
    r.bic = number(e, "bic");
    r.delta_aic = number(e, "delta_aic");
    r.delta_bic = number(e, "delta_bic");
    r.held_out_q = number(e, "held_out_rms_q");
    r.held_out_p = number(e, "held_out_rms_p");
    r.held_out_eps_v = number(e, "held_out_rms_eps_v");
    r.seconds = number(e, "seconds");
    if (e.contains("parameters"))
      r.parameters = e.at("parameters").get<std::vector<std::string>>();
    rungs.push_back(std::move(r));
  }
  return rungs;
}

} // namespace geocomp::compare

// `quadmc gallery`: see gallery_command.hpp. Each point set is computed by one thread from its
// own streams, so the numbers do not depend on how many threads share the sets.
#include "gallery_command.hpp"

#include "quadmc/core/errors.hpp"
#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/report/csv.hpp"
#include "quadmc/report/interruption.hpp"
#include "quadmc/report/provenance.hpp"
#include "quadmc/report/results_folder.hpp"
#include "quadmc/report/staged_output.hpp"
#include "quadmc/report/table_leaders.hpp"
#include "quadmc/sampling/discrepancy.hpp"
#include "quadmc/sampling/net_quality.hpp"
#include "quadmc/sampling/periodogram.hpp"
#include "quadmc/sampling/point_file.hpp"
#include "quadmc/sampling/zsobol_points.hpp"

#include "build_provenance.hpp"
#include "cli_validators.hpp"
#include "plot_script.hpp"
#include "progress_bar.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace quadmc_cli {

namespace interruption = quadmc::interruption;

namespace fs = std::filesystem;

namespace {

constexpr std::size_t dimension = 2;
constexpr std::array<std::uint64_t, 3> scatter_sizes{16, 64, 256};
constexpr std::uint64_t spectrum_size = 1024;
// The sizes of the discrepancy table: the scatter's and the spectrum's.
constexpr std::array<std::uint64_t, 4> gallery_sizes{16, 64, 256, spectrum_size};
// √1024 = 32 is the mean point spacing's frequency; twice that shows the high-frequency plateau.
constexpr std::size_t spectrum_radius = 64;
constexpr std::uint64_t max_discrepancy_realizations = 32;
constexpr std::array<std::string_view, 9> gallery_files{
    "README.md",    "meta.csv",    "scatter.csv", "strata.csv",     "discrepancy.csv",
    "spectrum.csv", "gallery.png", "spectra.png", "user_points.csv"};
// Written only with --points (the user's sets, their templates and realizations per N), so that a
// gallery without them writes the files it always wrote.
constexpr std::string_view user_points_file = "user_points.csv";
// A user's set name is a CSV field, a legend entry and a Markdown table cell: these characters
// need no quoting in any of them, and the length keeps the plan's and the page's columns readable.
constexpr std::size_t max_user_name = 40;

// One row of the gallery: a set of the catalogue, or a user's files (--points).
struct gallery_set {
  std::string name;
  const quadmc::point_set_entry* entry = nullptr;  // null: a user's set
  std::string path_template;                       // a user's set: as given
  // Per size of gallery_sizes, the realizations there are: R for a set of the catalogue; for a
  // user's set, the files r = 0, 1, … that exist (up to what the size uses, 1 without "{r}").
  std::array<std::uint64_t, gallery_sizes.size()> realizations{};
};

// The strata a set fills with one point each in 2D, as the set states them
// (point_set_entry::strata_of, with the reasons beside each set's entry); the gallery's tests
// count the points per stratum of every grid listed here. A user's set states none.
std::optional<quadmc::point_strata> strata_of(const gallery_set& set, std::uint64_t n) {
  if (set.entry == nullptr) return std::nullopt;
  return set.entry->strata_of(dimension, n);
}

struct discrepancy_row {
  std::uint64_t n = 0;
  quadmc::l2_discrepancies shown;  // of stream 0, the pictured points
  quadmc::l2_discrepancies rms;    // root mean square over the realizations
  std::uint64_t realizations = 0;
  // sampling/net_quality.hpp over the same realizations (every gallery size is 2^m): the largest
  // t-value, and the mean minimum distance over the densest packing's.
  unsigned t_value_max = 0;
  double min_distance_mean = 0.0;
};

struct set_result {
  const gallery_set* set = nullptr;
  std::vector<std::vector<double>> scatter;  // per scatter size, row-major (x, y)
  std::vector<discrepancy_row> discrepancy;
  std::vector<quadmc::radial_power_bin> spectrum;
  double seconds = 0.0;
};

// zsobol's points belong to an image: the gallery shows the first 2 × 2 tile of pixels, N/4
// samples each, in Morton order, one after the other (pixel (0, 0) first): each pixel's points
// are a scrambled (0, m − 2, 2)-net and the tile's together a (0, m, 2)-net, the structure that
// makes neighbouring pixels' errors cancel (sampling/zsobol_points.hpp).
std::vector<double> zsobol_tile(std::uint64_t n, std::uint64_t seed, std::uint64_t stream) {
  const quadmc::zsobol_points z(2, 2, n / 4, seed, stream);
  std::vector<double> x(n * dimension);
  const std::size_t per_pixel = static_cast<std::size_t>(n / 4) * dimension;
  for (std::size_t p = 0; p < 4; ++p) {
    z.generate(p % 2, p / 2, std::span<double>(x).subspan(p * per_pixel, per_pixel));
  }
  return x;
}

// Realization `stream` of N points: the set's stream of seed K (zsobol: its tile), or a user's
// file r = stream, read again as the plan read it (read_point_file checks it again, so a file
// changed since is refused in one line, before anything is written).
std::vector<double> points_of(const gallery_set& set, std::uint64_t n, std::uint64_t seed,
                              std::uint64_t stream) {
  if (set.entry == &quadmc::zsobol_render_set()) return zsobol_tile(n, seed, stream);
  if (set.entry == nullptr) {
    return quadmc::read_point_file(quadmc::point_file_path(set.path_template, n, stream),
                                   quadmc::point_file_columns::points, n, dimension)
        .x;
  }
  std::vector<double> x(n * dimension);
  set.entry->points(
      dimension, n, {seed, stream}, [&](std::uint64_t first, std::span<const double> b) {
        std::copy(b.begin(), b.end(), x.begin() + static_cast<std::ptrdiff_t>(first * dimension));
      });
  return x;
}

// The expected squares for N independent uniform points in s = 2 (sampling/discrepancy.hpp):
// the reference the table sets every row beside.
quadmc::l2_discrepancies independent_rms(std::uint64_t n) {
  const double N = static_cast<double>(n);
  return {std::sqrt((1.0 / 4 - 1.0 / 9) / N), std::sqrt((25.0 / 16 - 169.0 / 144) / N),
          std::sqrt((9.0 / 4 - 16.0 / 9) / N)};
}

class gallery_progress {
 public:
  explicit gallery_progress(std::uint64_t total) : total_(total) {}
  void add(std::uint64_t done, bool set_finished) {
    const std::lock_guard lock(mutex_);
    done_ += done;
    if (set_finished) ++sets_done_;
    const auto held = interruption::hold();
    bar_.update({sets_done_, sets_total, done_, total_});
  }
  void finish() {
    const std::lock_guard lock(mutex_);
    const auto held = interruption::hold();
    bar_.finish();
  }
  std::size_t sets_total = 0;

 private:
  std::mutex mutex_;
  progress_bar bar_;
  std::uint64_t total_;
  std::uint64_t done_ = 0;
  std::size_t sets_done_ = 0;
};

set_result compute_set(const gallery_set& set, const gallery_request& r,
                       gallery_progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  set_result out;
  out.set = &set;
  for (std::size_t k = 0; k < gallery_sizes.size(); ++k) {
    const std::uint64_t n = gallery_sizes[k];
    const std::uint64_t d_realizations =
        std::min(set.realizations[k], max_discrepancy_realizations);
    discrepancy_row row;
    row.n = n;
    row.realizations = d_realizations;
    std::array<double, 3> squares{0.0, 0.0, 0.0};
    for (std::uint64_t stream = 0; stream < d_realizations; ++stream) {
      const std::vector<double> x = points_of(set, n, r.seed, stream);
      const quadmc::l2_discrepancies d = quadmc::discrepancies(x, dimension);
      if (stream == 0) {
        row.shown = d;
        if (n != spectrum_size) out.scatter.push_back(x);
      }
      squares[0] += d.l2_star * d.l2_star;
      squares[1] += d.centered * d.centered;
      squares[2] += d.wraparound * d.wraparound;
      row.t_value_max = std::max(row.t_value_max, *quadmc::net_t_value(x, dimension));
      row.min_distance_mean += quadmc::normalized_min_distance(x, dimension);
    }
    const double R = static_cast<double>(d_realizations);
    row.min_distance_mean /= R;
    row.rms = {std::sqrt(squares[0] / R), std::sqrt(squares[1] / R), std::sqrt(squares[2] / R)};
    out.discrepancy.push_back(row);
  }
  quadmc::radial_periodogram spectrum(spectrum_radius);
  const std::uint64_t s_realizations = set.realizations.back();
  for (std::uint64_t stream = 0; stream < s_realizations; ++stream) {
    spectrum.add(points_of(set, spectrum_size, r.seed, stream));
    progress.add(1, stream + 1 == s_realizations);
  }
  out.spectrum = spectrum.bins();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

void write_file(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
}

std::string line(std::initializer_list<std::string> fields) {
  const std::vector<std::string> v(fields);
  return quadmc::csv_line(v);
}

std::string number(double x) {
  return fmt::format("{}", x);
}

std::string scatter_csv(const std::vector<set_result>& results) {
  std::string text = line({"set", "n", "index", "x1", "x2"});
  for (const set_result& r : results) {
    for (std::size_t k = 0; k < scatter_sizes.size(); ++k) {
      const std::vector<double>& x = r.scatter[k];
      for (std::size_t i = 0; i < x.size() / dimension; ++i) {
        text += line({std::string(r.set->name), std::to_string(scatter_sizes[k]), std::to_string(i),
                      number(x[2 * i]), number(x[2 * i + 1])});
      }
    }
  }
  return text;
}

std::string strata_csv(const std::vector<set_result>& results) {
  std::string text = line({"set", "n", "kind", "columns", "rows"});
  for (const set_result& r : results) {
    for (const std::uint64_t n : scatter_sizes) {
      if (const auto g = strata_of(*r.set, n)) {
        text += line({std::string(r.set->name), std::to_string(n),
                      std::string(quadmc::to_string(g->kind)), std::to_string(g->per_axis),
                      std::to_string(g->per_axis)});
      }
    }
  }
  return text;
}

std::string discrepancy_csv(const std::vector<set_result>& results) {
  std::string text =
      line({"set", "n", "realizations", "l2_star", "centered", "wraparound", "l2_star_rms",
            "centered_rms", "wraparound_rms", "t_value_max", "min_distance_ratio_mean"});
  for (const set_result& r : results) {
    for (const discrepancy_row& d : r.discrepancy) {
      text += line({std::string(r.set->name), std::to_string(d.n), std::to_string(d.realizations),
                    number(d.shown.l2_star), number(d.shown.centered), number(d.shown.wraparound),
                    number(d.rms.l2_star), number(d.rms.centered), number(d.rms.wraparound),
                    std::to_string(d.t_value_max), number(d.min_distance_mean)});
    }
  }
  return text;
}

std::string spectrum_csv(const std::vector<set_result>& results) {
  std::string text =
      line({"set", "n", "realizations", "radius", "frequencies", "mean_power", "standard_error"});
  for (const set_result& r : results) {
    for (const quadmc::radial_power_bin& b : r.spectrum) {
      text += line({std::string(r.set->name), std::to_string(spectrum_size),
                    std::to_string(r.set->realizations.back()), std::to_string(b.radius),
                    std::to_string(b.frequencies), number(b.mean_power), number(b.standard_error)});
    }
  }
  return text;
}

// One band of the spectrum: the mean power over the bins lo … hi (inclusive), weighted by their
// frequency counts, and its standard error from the bins' (their realizations' spread), taking
// the bins as independent: √(Σ (frequencies·se)²) / Σ frequencies.
struct band {
  double power = 0.0;
  double standard_error = 0.0;
};

band band_of(const std::vector<quadmc::radial_power_bin>& bins, std::size_t lo, std::size_t hi) {
  double power = 0.0;
  double variance = 0.0;
  double count = 0.0;
  for (const auto& b : bins) {
    if (b.radius < lo || b.radius > hi) continue;
    const double f = static_cast<double>(b.frequencies);
    power += b.mean_power * f;
    variance += f * f * b.standard_error * b.standard_error;
    count += f;
  }
  return {power / count, std::sqrt(variance) / count};
}

// The bands of the page's spectrum table, in |f|.
constexpr std::array<std::array<std::size_t, 2>, 4> spectrum_bands{
    {{1, 8}, {9, 24}, {25, 40}, {41, 64}}};

// The answer at the top of the page, read from its two tables (report/table_leaders.hpp): who has
// the smallest discrepancies as N grows, which sets have the least low-frequency power, and which
// have power above white noise, where structure (a lattice, a grid) shows as spikes.
std::vector<std::string> answer_lines(const std::vector<set_result>& results) {
  std::vector<std::string> lines;
  const auto discrepancy_table = [&](double quadmc::l2_discrepancies::*which) {
    quadmc::scored_table t{"N", {gallery_sizes.begin(), gallery_sizes.end()}, {}, {}};
    for (const set_result& s : results) {
      t.rows.push_back(s.set->name);
      std::vector<std::optional<double>> values(t.columns.size());
      for (const discrepancy_row& d : s.discrepancy) {
        const auto k = std::find(t.columns.begin(), t.columns.end(), d.n) - t.columns.begin();
        if (k < static_cast<long>(values.size()))
          values[static_cast<std::size_t>(k)] = d.rms.*which;
      }
      t.values.push_back(std::move(values));
    }
    return t;
  };
  lines.push_back(
      "**Smallest L2-star discrepancy** (root mean square over the realizations): " +
      quadmc::leaders_phrase(discrepancy_table(&quadmc::l2_discrepancies::l2_star), "independent") +
      ".");
  lines.push_back(
      "**Smallest wrap-around discrepancy** (the one that sees a lattice's periodicity): " +
      quadmc::leaders_phrase(discrepancy_table(&quadmc::l2_discrepancies::wraparound),
                             "independent") +
      ".");
  // Low frequencies: every set, least power first (what blue noise means here).
  std::vector<std::pair<double, std::string>> low;
  for (const set_result& s : results) {
    low.emplace_back(band_of(s.spectrum, spectrum_bands[0][0], spectrum_bands[0][1]).power,
                     s.set->name);
  }
  std::stable_sort(low.begin(), low.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> ranked;
  for (const auto& [power, set] : low) ranked.push_back(fmt::format("`{}` {:.3f}", set, power));
  lines.push_back(fmt::format(
      "**Least power at low frequencies** ({} ≤ |f| ≤ {}, N = {}; white noise is 1): {}.",
      spectrum_bands[0][0], spectrum_bands[0][1], spectrum_size, fmt::join(ranked, ", ")));
  // Power above white noise beyond its statistics: more than 4 standard errors and 5 % above 1.
  std::vector<std::string> spikes;
  for (const set_result& s : results) {
    std::vector<std::string> bands;
    for (const auto& [lo, hi] : spectrum_bands) {
      const band b = band_of(s.spectrum, lo, hi);
      if (b.power > 1.05 && b.power - 1.0 > 4.0 * b.standard_error) {
        bands.push_back(fmt::format("{:.3f} at {}–{}", b.power, lo, hi));
      }
    }
    if (!bands.empty())
      spikes.push_back(fmt::format("`{}` {}", s.set->name, fmt::join(bands, ", ")));
  }
  lines.push_back(spikes.empty() ? std::string("**Power above white noise:** no band of any set is "
                                               "more than 5 % and 4 standard errors above 1.")
                                 : fmt::format("**Power above white noise** (a band more than 5 % "
                                               "and 4 standard errors above 1: structure, not "
                                               "noise): {}.",
                                               fmt::join(spikes, "; ")));
  return lines;
}

// A set's name in the page's tables: a user's set says so (its realizations are in the section
// on the user's sets).
std::string table_name(const gallery_set& set) {
  return set.entry == nullptr ? fmt::format("{} *(--points)*", set.name) : set.name;
}

// The page's section on the user's sets (--points), empty without them: which rows are theirs,
// from which files, and how many realizations each of their numbers averages.
std::string user_sets_section(const std::vector<set_result>& results, const gallery_request& r) {
  std::string rows;
  for (const set_result& s : results) {
    const gallery_set& g = *s.set;
    if (g.entry != nullptr) continue;
    rows += fmt::format("| {} | `{}` | {} | {} | {} | {} |\n", g.name, g.path_template,
                        g.realizations[0], g.realizations[1], g.realizations[2], g.realizations[3]);
  }
  if (rows.empty()) return {};
  std::string t = "## Your point sets (--points)\n\n";
  t += fmt::format(
      "The last rows are point sets read from files, not made by the suite: their points are "
      "those of the files r = 0, 1, … at each N (a template without {{r}} is one realization), "
      "counted up to the first missing file and up to what the suite's sets use (min(R, {}) = {} "
      "for the discrepancies' RMS at N = 16, 64, 256; R = {} for the spectrum at N = {}). A "
      "user's set has no strata drawn: its files state none. Its spectrum averages the "
      "realizations below instead of R (with one, the standard error is nan and no band is "
      "drawn); its RMS discrepancy averages min(realizations, {}). The scatter shows r = 0. "
      "Relative templates were read from the folder the command ran in.\n\n",
      max_discrepancy_realizations, std::min(r.realizations, max_discrepancy_realizations),
      r.realizations, spectrum_size, max_discrepancy_realizations);
  t += "| set | files | realizations at N = 16 | 64 | 256 | 1024 |\n|---|---|---|---|---|---|\n";
  return t + rows + "\n";
}

std::string readme(const std::vector<set_result>& results, const gallery_request& r,
                   const quadmc::provenance& build, double seconds, unsigned threads) {
  std::string t;
  t += "# Point-set gallery\n\n";
  t += fmt::format(
      "Every point set of the suite in s = 2, side by side: where the points fall, their "
      "projections, their power spectrum and their L2 discrepancies. Made by `quadmc gallery` "
      "(seed {}, {} realizations for the spectra) in {:.1f} s on {} threads; quadmc {} "
      "(commit {}, {}).\n\n",
      r.seed, r.realizations, seconds, threads, build.version, build.commit, build.compiler);
  // The answer first, from the tables further down; a quotation, as on the run pages.
  for (const std::string& line : answer_lines(results)) t += fmt::format("> - {}\n", line);
  t += "\n";
  t += "![Scatter plots at N = 16, 64, 256 with strata, projections and spectra](gallery.png)\n\n";
  t += "## How to read it\n\n";
  t += fmt::format(
      "- **Scatter** (columns N = 16, 64, 256): the points of one realization. Grey lines are the "
      "strata the set fills with exactly one point each, where it has them by construction: a "
      "k × k grid (jittered, unjittered, padded; Sobol', a (0, m, 2)-net, at N = 4^j) or N rows "
      "and N columns (Latin hypercube, rank-1 lattice; drawn up to N = 64). The ticks below and "
      "left of each square are the 1D projections on x₁ and x₂: evenly spaced ticks mean a "
      "stratified projection, clumps and gaps mean an independent one. The numbers under a square "
      "are its L2-star, centered and wrap-around discrepancies D*, CD, WD.\n"
      "- **Spectrum** (last column, and `spectra.png` with every set on one plot): the radially "
      "averaged periodogram P(f) = |Σⱼ exp(−2πi f·xⱼ)|²/N over integer frequencies f with "
      "round(|f|) = r, averaged over {} independent realizations of N = {} points, with a band of "
      "±2 standard errors. Independent points are white noise, flat at 1; stratified points have "
      "low power below the frequency of their strata (√N = 32, dotted), blue noise, and the "
      "grid of centres (unjittered) has all its power in spikes at the multiples of √N.\n"
      "- **padded_jittered equals jittered here**: in s = 2 the padded set is one 2D group, whose "
      "permutation is the identity and whose jitter uses the same uniform numbers, so its points "
      "are the jittered points; padding shuffles strata across dimension pairs only from s = 3 "
      "on.\n"
      "- **zsobol** samples images (`quadmc render` only): its row is the first 2 × 2 tile of "
      "pixels of an image, N/4 samples each, one pixel after the other in Morton order. Each "
      "pixel's points are a scrambled (0, m − 2, 2)-net and the four together a (0, m, 2)-net, "
      "so the tile looks like `sobol`; what the shared net buys, errors that cancel between "
      "neighbouring pixels, is measured on the render page (results/render).\n"
      "- **Discrepancy table** below: the discrepancies of the pictured points and their root "
      "mean square over min(R, 32) realizations, beside the expected value for independent "
      "points, √((2⁻ˢ − 3⁻ˢ)/N) etc. (sampling/discrepancy.hpp).\n\n",
      r.realizations, spectrum_size);
  t += user_sets_section(results, r);
  t += "![Radially averaged power spectra of all point sets](spectra.png)\n\n";
  t += fmt::format("## Power spectrum at N = {}, {} realizations\n\n", spectrum_size,
                   r.realizations);
  t += "Mean power (frequency-weighted) in four bands of |f|; 1 is white noise.\n\n";
  t += "| point set |";
  for (const auto& [lo, hi] : spectrum_bands) t += fmt::format(" {} ≤ \\|f\\| ≤ {} |", lo, hi);
  t += "\n|---|";
  for (std::size_t k = 0; k < spectrum_bands.size(); ++k) t += "---|";
  t += "\n";
  for (const set_result& s : results) {
    t += fmt::format("| {} |", table_name(*s.set));
    for (const auto& [lo, hi] : spectrum_bands) {
      t += fmt::format(" {:.3f} |", band_of(s.spectrum, lo, hi).power);
    }
    t += "\n";
  }
  t += "\n## L2 discrepancies\n\n";
  t += "Pictured realization (root mean square over the realizations in brackets); t: the largest "
       "t-value of the realizations as (t, m, 2)-nets, N = 2^m (0: every elementary interval of "
       "area 1/N holds one point); δ: the mean minimum distance over the hexagonal packing's "
       "(sampling/net_quality.hpp).\n\n";
  t += "| point set | N | D* | CD | WD | t | δ |\n|---|---|---|---|---|---|---|\n";
  for (const std::uint64_t n : gallery_sizes) {
    const quadmc::l2_discrepancies e = independent_rms(n);
    t += fmt::format("| *independent, expected* | {} | {:.4f} | {:.4f} | {:.4f} | | |\n", n,
                     e.l2_star, e.centered, e.wraparound);
    for (const set_result& s : results) {
      for (const discrepancy_row& d : s.discrepancy) {
        if (d.n != n) continue;
        t += fmt::format(
            "| {} | {} | {:.4f} ({:.4f}) | {:.4f} ({:.4f}) | {:.4f} ({:.4f}) | {} | {:.3f} |\n",
            table_name(*s.set), n, d.shown.l2_star, d.rms.l2_star, d.shown.centered, d.rms.centered,
            d.shown.wraparound, d.rms.wraparound, d.t_value_max, d.min_distance_mean);
      }
    }
  }
  t += "\n## Files\n\n";
  t += "`scatter.csv` (set, n, index, x1, x2), `strata.csv` (set, n, kind, columns, rows), "
       "`spectrum.csv` (set, n, realizations, radius, frequencies, mean_power, standard_error), "
       "`discrepancy.csv` (set, n, realizations, l2_star, centered, wraparound and their _rms, "
       "t_value_max, min_distance_ratio_mean), "
       "`meta.csv` (what built the command). Regenerate with `quadmc gallery` "
       "(`build/release/bench/quadmc gallery`).\n";
  if (results.back().set->entry == nullptr) {
    t += "`user_points.csv` (set, template, n, realizations): the user's sets (--points).\n";
  }
  t += "\nTime per point set (one thread each): ";
  for (std::size_t i = 0; i < results.size(); ++i) {
    t += fmt::format("{}{} {:.1f} s", i == 0 ? "" : ", ", results[i].set->name, results[i].seconds);
  }
  t += ".\n";
  return t;
}

std::string user_points_csv(const std::vector<gallery_set>& sets) {
  std::string text = line({"set", "template", "n", "realizations"});
  for (const gallery_set& g : sets) {
    if (g.entry != nullptr) continue;
    for (std::size_t k = 0; k < gallery_sizes.size(); ++k) {
      text += line({g.name, g.path_template, std::to_string(gallery_sizes[k]),
                    std::to_string(g.realizations[k])});
    }
  }
  return text;
}

struct points_option {
  std::string name;
  std::string path_template;
};

// Splits and checks one --points value: the empty string, or what was expected of it.
std::string points_option_problem(std::string_view text, points_option& out) {
  const std::size_t eq = text.find('=');
  const auto got = [&](std::string_view why) {
    return fmt::format("expected NAME=PATH_TEMPLATE (e.g. mine=pts/{{N}}_{{r}}.csv), got '{}': {}",
                       text, why);
  };
  if (eq == std::string_view::npos) return got("no '='");
  out.name = std::string(text.substr(0, eq));
  out.path_template = std::string(text.substr(eq + 1));
  const bool safe = std::all_of(out.name.begin(), out.name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
  if (out.name.empty() || out.name.size() > max_user_name || !safe) {
    return got(fmt::format("NAME must be 1 to {} letters, digits, '_' or '-'", max_user_name));
  }
  if (quadmc::find_point_set(out.name) != nullptr || out.name == quadmc::zsobol_render_set().name) {
    return got("NAME is a point set of the suite; choose another");
  }
  if (out.path_template.find("{N}") == std::string::npos) {
    return got("PATH_TEMPLATE needs {N} (one file per N = 16, 64, 256, 1024)");
  }
  return {};
}

// The realizations of a user's set at N: the files r = 0, 1, … up to `wanted` (1 without "{r}"),
// until the first that does not exist; r = 0 must. Each is read and checked (N rows, s = 2, every
// coordinate in [0, 1)) here, before any computation, so a bad file costs nothing.
std::uint64_t count_realizations(const points_option& p, std::uint64_t n, std::uint64_t wanted) {
  const bool numbered = p.path_template.find("{r}") != std::string::npos;
  std::uint64_t r = 0;
  for (; r < (numbered ? wanted : 1); ++r) {
    const fs::path file = quadmc::point_file_path(p.path_template, n, r);
    std::error_code ignored;  // any other failure than absence: read_point_file says which
    if (r > 0 && fs::status(file, ignored).type() == fs::file_type::not_found) break;
    try {
      (void)quadmc::read_point_file(file, quadmc::point_file_columns::points, n, dimension);
    } catch (const quadmc::invalid_argument& e) {
      throw std::runtime_error(
          fmt::format("--points {}={}: {}", p.name, p.path_template, e.what()));
    }
  }
  return r;
}

// The rows of the gallery: the catalogue's sets that hold every size (the others in `skipped`),
// then the user's sets in the order given, their files counted and checked.
std::vector<gallery_set> plan_sets(const gallery_request& r, std::vector<std::string>& skipped) {
  std::vector<gallery_set> sets;
  for (const quadmc::point_set_entry& set : quadmc::point_set_catalogue()) {
    std::string problem;
    for (const std::uint64_t n : gallery_sizes) {
      if (problem.empty()) problem = quadmc::size_problem(set, dimension, n);
    }
    if (problem.empty()) {
      gallery_set g{std::string(set.name), &set, {}, {}};
      g.realizations.fill(r.realizations);
      sets.push_back(std::move(g));
    } else {
      skipped.push_back(fmt::format("{}: {}", set.name, problem));
    }
  }
  // The render's own set, as the 2 × 2 tile of pixels zsobol_tile draws (every size is 4·2^k).
  gallery_set tile{
      std::string(quadmc::zsobol_render_set().name), &quadmc::zsobol_render_set(), {}, {}};
  tile.realizations.fill(r.realizations);
  sets.push_back(std::move(tile));
  for (const std::string& text : r.points) {
    points_option p;
    const std::string problem = points_option_problem(text, p);
    if (!problem.empty()) throw std::runtime_error(fmt::format("--points: {}", problem));
    gallery_set g{p.name, nullptr, p.path_template, {}};
    for (std::size_t k = 0; k < gallery_sizes.size(); ++k) {
      const bool spectrum = gallery_sizes[k] == spectrum_size;
      g.realizations[k] = count_realizations(
          p, gallery_sizes[k],
          spectrum ? r.realizations : std::min(r.realizations, max_discrepancy_realizations));
    }
    sets.push_back(std::move(g));
  }
  return sets;
}

std::string plan_text(const std::vector<gallery_set>& sets, std::size_t user_sets,
                      const std::vector<std::string>& skipped, const gallery_request& r,
                      unsigned threads, const fs::path& folder) {
  const std::string counted = user_sets == 0
                                  ? fmt::format("{} point sets", sets.size())
                                  : fmt::format("{} point sets and {} from files (--points)",
                                                sets.size() - user_sets, user_sets);
  std::string plan = fmt::format(
      "gallery: {} in s = 2 (seed {}), {} threads → {}\n"
      "  scatter, strata and 1D projections at N = 16, 64, 256 (stream 0)\n"
      "  radially averaged periodogram at N = {}, |f| = 1 … {}, over {} realizations per set\n"
      "  L2-star, centered, wrap-around discrepancies at N = 16, 64, 256, {} (RMS over {} "
      "realizations)\n",
      counted, r.seed, threads, folder.string(), spectrum_size, spectrum_radius, r.realizations,
      spectrum_size, std::min(r.realizations, max_discrepancy_realizations));
  for (const gallery_set& s : sets) {
    if (s.entry == nullptr) {
      plan += fmt::format(
          "  {:<16} strata: none (files {}; realizations at N = 16, 64, 256, {}: {}, {}, {}, "
          "{})\n",
          s.name, s.path_template, spectrum_size, s.realizations[0], s.realizations[1],
          s.realizations[2], s.realizations[3]);
      continue;
    }
    std::string grids;
    for (const std::uint64_t n : scatter_sizes) {
      if (const auto g = strata_of(s, n)) {
        grids += fmt::format("{}N = {}: {} × {} {}", grids.empty() ? "" : ", ", n, g->per_axis,
                             g->per_axis, quadmc::to_string(g->kind));
      }
    }
    plan += fmt::format("  {:<16} strata: {}\n", s.name, grids.empty() ? "none" : grids);
  }
  for (const std::string& s : skipped) plan += fmt::format("  skipped {}\n", s);
  return plan;
}

// Computes every set, one set per thread at a time: the numbers do not depend on `threads`.
std::vector<set_result> compute_sets(const std::vector<gallery_set>& sets, const gallery_request& r,
                                     unsigned threads) {
  std::uint64_t total = 0;
  for (const gallery_set& g : sets) total += g.realizations.back();
  gallery_progress progress(total);
  progress.sets_total = sets.size();
  std::vector<set_result> results(sets.size());
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> errors(threads);
  {
    std::vector<std::jthread> workers;
    for (unsigned w = 0; w < threads; ++w) {
      workers.emplace_back([&, w] {
        try {
          for (std::size_t i = next++; i < sets.size(); i = next++) {
            results[i] = compute_set(sets[i], r, progress);
          }
        } catch (...) {
          errors[w] = std::current_exception();
        }
      });
    }
  }
  progress.finish();
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  return results;
}

}  // namespace

CLI::App* add_gallery_subcommand(CLI::App& app, gallery_request& request) {
  auto* gallery = app.add_subcommand(
      "gallery",
      "Draw every point set in 2D (scatter, strata, projections, power spectrum, discrepancies) "
      "into results/gallery/");
  gallery->add_option("--out", request.out, "Output folder (default: results/gallery)")
      ->check(quadmc_cli::non_empty_path());
  gallery
      ->add_option("--realizations", request.realizations,
                   "Independent realizations averaged in each power spectrum, 2 to 100000 "
                   "(default 256)")
      ->check(CLI::Range(std::uint64_t{2}, std::uint64_t{100000}));
  gallery->add_option("--seed", request.seed, "Seed K ≥ 0 (the Philox key, default 2026)")
      ->check(non_negative_integer());
  gallery
      ->add_option("--threads", request.threads,
                   "Threads, 0 = all cores, at most 4096 (default 0; one point set per thread)")
      ->check(CLI::Range(0u, 4096u));
  gallery
      ->add_option("--points", request.points,
                   "A row of your own points, repeatable: NAME=PATH_TEMPLATE, files (CSV or .npy, "
                   "s = 2) with {N} and {r} replaced by N = 16, 64, 256, 1024 and r = 0, 1, … "
                   "(as many as exist, up to R)")
      ->check(CLI::Validator(
          [](std::string& text) {
            points_option p;
            return points_option_problem(text, p);
          },
          "NAME=PATH_TEMPLATE"));
  // Two rows of one name would be one row in the CSVs: refused with the usage errors (exit 2).
  gallery->callback([&request] {
    std::vector<std::string> names;
    for (const std::string& text : request.points) {
      points_option p;
      (void)points_option_problem(text, p);
      if (std::find(names.begin(), names.end(), p.name) != names.end()) {
        throw CLI::ValidationError(
            "--points",
            fmt::format("expected each NAME once, got '{}' twice (in '{}')", p.name, text));
      }
      names.push_back(p.name);
    }
  });
  return gallery;
}

bool is_gallery_file_name(std::string_view name) {
  return std::find(gallery_files.begin(), gallery_files.end(), name) != gallery_files.end();
}

void run_gallery(const gallery_request& r, const std::function<void(std::string_view)>& print) {
  const quadmc::provenance build = quadmc::bench::build_provenance();
  std::vector<std::string> skipped;
  const std::vector<gallery_set> sets = plan_sets(r, skipped);
  const std::size_t user_sets = r.points.size();

  const bool given = !r.out.empty();
  const fs::path folder = quadmc::results_folder_path(r.out, "gallery");
  std::vector<std::string> files(gallery_files.begin(), gallery_files.end());
  if (user_sets == 0) std::erase(files, std::string(user_points_file));
  quadmc::staged_output staged("gallery", given ? "--out" : "results folder",
                               given ? r.out : std::string("results/gallery"), folder, files,
                               &is_gallery_file_name);
  check_plotting(gallery_script_path(), "to draw the gallery");

  const unsigned cores = r.threads == 0 ? std::thread::hardware_concurrency() : r.threads;
  const unsigned threads = std::max(1u, std::min(cores, static_cast<unsigned>(sets.size())));
  print(plan_text(sets, user_sets, skipped, r, threads, folder));
  if (sets.size() == user_sets) {
    throw std::runtime_error("gallery: no point set holds N = 16, 64, 256, 1024");
  }

  const auto start = std::chrono::steady_clock::now();
  const std::vector<set_result> results = compute_sets(sets, r, threads);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  staged.write([&](const fs::path& dir) {
    write_file(dir / "scatter.csv", scatter_csv(results));
    write_file(dir / "strata.csv", strata_csv(results));
    write_file(dir / "discrepancy.csv", discrepancy_csv(results));
    write_file(dir / "spectrum.csv", spectrum_csv(results));
    write_file(dir / std::string(quadmc::meta_csv_file), quadmc::meta_csv_text(build));
    write_file(dir / "README.md", readme(results, r, build, seconds, threads));
    if (user_sets > 0) write_file(dir / std::string(user_points_file), user_points_csv(sets));
  });
  staged.run_child(quadmc::plot_command_line(gallery_script_path(), staged.staging()));
  const quadmc::staged_output::committed done = staged.commit();
  print(fmt::format("gallery: {} point sets in {:.1f} s on {} threads; {}\n", sets.size(), seconds,
                    threads, done.written));
  if (!done.warning.empty()) fmt::print(stderr, "quadmc: warning: {}\n", done.warning);
}

}  // namespace quadmc_cli

// control = "tolerance" for the sample-mean methods (the quasi-Monte Carlo sets of qmc.cpp, plain
// Monte Carlo and the stratified sets of point_set_methods.cpp): the `stopping` key, its
// parameters, and one cell run by the rule (estimators/stopping_rules.hpp;
// docs/theory.md#stopping-rules). Private to the methods layer.
//
// The rules a set can take follow from what it is, never from its name:
//   replicates   an extensible set (point_set_entry::extensible) that is random: R randomizations;
//   guaranteed   a digitally shifted Sobol' net (randomization "shift" or "lms_shift": its error is
//                the sum of Walsh coefficients over the dual net, which an Owen scramble does not
//                keep), the shifted lattice, or independent points (Berry–Esseen);
//   clt          a set whose one run estimates its own error (error_source::own).
// Without `stopping` a cell to a tolerance takes clt where the set estimates its own error, else
// replicates. Every key is refused at its name when the method is not run to a tolerance, or
// when the rule chosen does not read it.
#pragma once

#include "quadmc/estimators/point_set_catalogue.hpp"
#include "quadmc/estimators/stopping_rules.hpp"
#include "quadmc/methods/method.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace quadmc::methods {

enum class stopping_rule { replicates, guaranteed, clt };

struct stopping_choice {
  std::optional<stopping_rule> rule;  // the rule the cells use; empty: none fits the set
  std::string why_none;               // …and why
  bool given = false;                 // `stopping` was set (it then joins the label)
  std::vector<std::string> keys;      // the stopping keys the table set, in reading order
  replicate_stopping_options replicates;
  guaranteed_qmc_options guaranteed;
  two_stage_options two_stage;

  // "_replicates" etc. when `stopping` was given.
  std::string label_suffix() const;
  // Why the method cannot run under `control` with these keys: the key and the message.
  std::optional<control_refusal> refuses(cell_control control) const;
};

// The option docs of the stopping keys, appended to a method's own (constant: descriptors read
// them during static initialization).
inline constexpr std::array<option_doc, 7> stopping_docs{{
    {"stopping",
     "with control = \"tolerance\": \"replicates\" (R randomizations, N doubled until the "
     "Student-t half-width <= tolerance), \"guaranteed\" (sobol with randomization \"shift\" or "
     "\"lms_shift\", lattice: the cone-based Walsh/Fourier bound; plain_mc: Berry-Esseen), "
     "\"clt\" (pilot, then a CLT-sized sample); default clt where one run estimates its own "
     "error, else replicates; the label gets \"_<stopping>\""},
    {"replications", "stopping = \"replicates\": R >= 2 randomizations (default 16)"},
    {"n_init",
     "with control = \"tolerance\": the first N (replicates: per replicate, default 256; "
     "guaranteed nets: 1024; clt and guaranteed plain_mc: the pilot, 1024); a power of two but "
     "for the pilots"},
    {"alpha",
     "replicates, clt, guaranteed plain_mc: the uncertainty of the 1 - alpha claim (default "
     "0.01)"},
    {"inflate",
     "replicates (default 1), clt and guaranteed plain_mc (default 1.2): the factor on the "
     "estimated standard deviation"},
    {"fudge", "stopping = \"guaranteed\" on sobol or lattice: C of the bound C*2^-m*S (default 5)"},
    {"r_lag",
     "stopping = \"guaranteed\" on sobol or lattice: the coefficients the bound sums, "
     "2^(m-r-1) ... 2^(m-r) - 1 (default 4)"},
}};

// Reads `stopping` and its parameters for the set with these options.
stopping_choice read_stopping(option_reader& r, const point_set_entry& set,
                              const point_set_options& options);

// The budget's sizing for a cell to a tolerance: the reason when the budget cannot hold the
// rule's first stage.
sizing stopping_sizing(const stopping_choice& c, const point_set_entry& set,
                       const point_set_options& options, std::uint64_t budget, std::size_t s);

// Whether a cell to a tolerance shares its chunks between the processes of a split cell: the
// two-stage rules run the set's sample mean, which does; the doubling rules keep every value
// (sample_values.hpp), computed whole on every process.
bool stopping_shares_chunks(const stopping_choice& c, const point_set_entry& set);

// One repetition of a cell to cell.tolerance: value, evaluations spent, and the claim as its
// error estimate.
repetition_result run_stopping(const stopping_choice& c, const point_set_entry& set,
                               const point_set_options& options, const method_cell& cell,
                               const run_context& context);

}  // namespace quadmc::methods

//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// A Google Benchmark console reporter that also prints, at the end, every
// benchmark's time per item as a ratio to one baseline benchmark measured in
// the same run.  With --benchmark_repetitions=N each time is the median of
// the N repetitions (on a shared machine a single run can be off by 20 %).
// Use from a benchmark program's main():
//   spinslide_bench::ratio_reporter reporter("baseline_name");
//   benchmark::RunSpecifiedBenchmarks(&reporter);
#ifndef SPINSLIDE_BENCHMARKS_RATIO_REPORTER_HPP
#define SPINSLIDE_BENCHMARKS_RATIO_REPORTER_HPP

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace spinslide_bench {

class ratio_reporter : public benchmark::ConsoleReporter {
 public:
  explicit ratio_reporter(std::string baseline,
                          std::vector<std::pair<std::string, std::string>> comparisons = {})
      : baseline_(std::move(baseline)), comparisons_(std::move(comparisons)) {}

  /// Also print "first costs N times second".
  void add_comparison(std::string first, std::string second) {
    comparisons_.emplace_back(std::move(first), std::move(second));
  }

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration || r.error_occurred) continue;
      const auto items = r.counters.find("items_per_second");
      if (items == r.counters.end() || items->second.value <= 0) continue;
      const std::string name = r.benchmark_name();
      auto same = std::find_if(times_.begin(), times_.end(),
                               [&](const auto& t) { return t.first == name; });
      if (same == times_.end()) same = times_.insert(times_.end(), {name, {}});
      same->second.push_back(1e9 / items->second.value);
    }
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    results_.clear();
    for (const auto& t : times_) results_.emplace_back(t.first, median(t.second));
    double base = 0;
    for (const auto& r : results_)
      if (r.first == baseline_) base = r.second;
    std::printf("\n%-52s %12s %14s\n", "benchmark", "ns per item", "vs baseline");
    for (const auto& r : results_) {
      if (base > 0)
        std::printf("%-52s %12.2f %13.3gx\n", r.first.c_str(), r.second, base / r.second);
      else
        std::printf("%-52s %12.2f %14s\n", r.first.c_str(), r.second, "(no baseline)");
    }
    std::printf("baseline: %s; 'Nx' means N times faster than the baseline.\n", baseline_.c_str());
    for (const auto& c : comparisons_) {
      double a = 0, b = 0;
      for (const auto& r : results_) {
        if (r.first == c.first) a = r.second;
        if (r.first == c.second) b = r.second;
      }
      if (a > 0 && b > 0)
        std::printf("%s costs %.2f times %s\n", c.first.c_str(), a / b, c.second.c_str());
    }
  }

 private:
  static double median(std::vector<double> x) {
    std::sort(x.begin(), x.end());
    const std::size_t n = x.size();
    return n % 2 ? x[n / 2] : (x[n / 2 - 1] + x[n / 2]) / 2;
  }

  std::string baseline_;
  std::vector<std::pair<std::string, std::string>> comparisons_;
  std::vector<std::pair<std::string, std::vector<double>>> times_;  // per repetition
  std::vector<std::pair<std::string, double>> results_;
};

}  // namespace spinslide_bench

#endif  // SPINSLIDE_BENCHMARKS_RATIO_REPORTER_HPP

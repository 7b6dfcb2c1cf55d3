//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file batch_throws.hpp
/// Many throws at once, spread over the machine's cores: every throw's stop
/// from simulate_throw (dynamics.hpp) or from a tabulated_throw
/// (tabulated_throw.hpp), in the order of the inputs.  Built on the public
/// single-throw calls only, so it is exactly as accurate as they are and gets
/// faster with them.
///
/// Thread safety.  The workers share the profile, or the table, by const
/// reference and call only its const members.  Every profile of spinslide is
/// safe to share so: a profile is immutable after construction, and the
/// quadratures some of them run keep their state in thread_local objects
/// (values/detail/ring_kernel.hpp, cylinder.hpp) or in statics initialised once
/// (C++11 guarantees that this is thread-safe).  radial_profile calls the
/// user's pressure p(r), which must then be safe to call from several threads
/// at once.  A tabulated_throw is a read-only table after construction.

#ifndef SPINSLIDE_MOTION_BATCH_THROWS_HPP
#define SPINSLIDE_MOTION_BATCH_THROWS_HPP

#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/tabulated_throw.hpp>
#include <spinslide/values/profile_concept.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <iterator>
#include <mutex>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace spinslide {

/// The start of one throw, dimensionless (the units of simulate_throw): a
/// named pair, so that speed and spin cannot be swapped silently.
template <class Real>
struct throw_start {
  using value_type = Real;  ///< the floating type
  Real v0;                  ///< the initial speed v0* (≥ 0)
  Real omega0;              ///< the initial spin ω0* (≥ 0)
};

/// A throw's stop from a tabulated_throw: its stop time and distance.
template <class Real>
struct tabulated_stop {
  using value_type = Real;  ///< the floating type
  Real time;                ///< the stop time t*
  Real distance;            ///< the distance slid s*
};

/// How a batch is run.
struct batch_options {
  /// The number of worker threads; 0 (the default) means
  /// std::thread::hardware_concurrency() (1 where that is unknown).
  unsigned threads = 0;
  /// Throws taken by a worker at a time; 0 (the default) chooses: enough
  /// pieces per thread that uneven throws balance, few enough that the shared
  /// counter is cheap.
  std::size_t chunk = 0;
  /// Called as progress(done, total) from the calling thread, at most once
  /// per `progress_interval`, and once with done == total at the end of a
  /// batch that succeeded.  May be empty.  An exception it throws stops the
  /// workers and reaches the caller.
  std::function<void(std::size_t done, std::size_t total)> progress;
  /// The least time between two calls of `progress`.
  std::chrono::milliseconds progress_interval{100};
};

namespace detail {

// The number of workers for `total` items: the requested count or the
// hardware's, at least 1 and at most one per item.
inline unsigned batch_threads(const batch_options& options, std::size_t total) {
  unsigned n = options.threads != 0 ? options.threads : std::thread::hardware_concurrency();
  n = (std::max)(n, 1U);
  return static_cast<unsigned>(
      (std::min)(static_cast<std::size_t>(n), (std::max)(total, std::size_t(1))));
}

// About 32 chunks per thread, at most 256 throws each: a 0.4 ms throw then
// makes chunks of at most 0.1 s, and the last chunks to finish leave the
// other threads idle for little of the batch.
inline std::size_t batch_chunk(const batch_options& options, std::size_t total, unsigned threads) {
  if (options.chunk != 0) return options.chunk;
  const std::size_t pieces = std::size_t(32) * threads;
  return (std::max)(std::size_t(1), (std::min)(std::size_t(256), total / pieces));
}

// out[i] = work(in[i]) for every i, on several threads.  Workers take chunks
// of consecutive indices from one atomic counter, so the order of the results
// is the order of the inputs whichever thread computes them.  An exception
// from work(in[i]) ends the batch as the serial loop would: the throws before
// i are still computed (a failure among them takes precedence), those after
// it are skipped, and the caller gets the exception of the smallest failing
// index.  The calling thread waits, calling progress.
template <class Iterator, class Work, class Result>
class batch_runner {
 public:
  batch_runner(Iterator first, Work work, std::vector<Result>& out, const batch_options& options)
      : first_(first),
        work_(std::move(work)),
        out_(out),
        options_(options),
        threads_(batch_threads(options, out.size())),
        chunk_(batch_chunk(options, out.size(), threads_)),
        first_failure_(out.size()) {}

  void run() {
    std::vector<std::thread> workers;
    workers.reserve(threads_);
    try {
      for (unsigned k = 0; k < threads_; ++k) workers.emplace_back([this] { work_loop(); });
      watch();
    } catch (...) {  // from progress, or a thread that could not start
      cancelled_ = true;
      for (std::thread& w : workers) w.join();
      throw;
    }
    for (std::thread& w : workers) w.join();
    if (failure_) std::rethrow_exception(failure_);
    if (options_.progress) options_.progress(out_.size(), out_.size());
  }

 private:
  void work_loop() {
    const std::size_t total = out_.size();
    for (;;) {
      const std::size_t begin = next_.fetch_add(chunk_);
      if (begin >= total || cancelled_) break;
      const std::size_t end = (std::min)(total, begin + chunk_);
      for (std::size_t i = begin; i < end && i < first_failure_.load(); ++i) {
        try {
          out_[i] = work_(first_[static_cast<difference>(i)]);
        } catch (...) {
          record_failure(i, std::current_exception());
        }
      }
      done_ += end - begin;
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    ++finished_;
    wake_.notify_one();
  }

  void record_failure(std::size_t i, std::exception_ptr e) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (i < first_failure_.load()) {
      first_failure_ = i;
      failure_ = std::move(e);
    }
  }

  // Waits for the workers, calling progress at most once per interval.
  void watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    const auto all_finished = [this] { return finished_ == threads_; };
    while (!all_finished()) {
      wake_.wait_for(lock, options_.progress_interval, all_finished);
      if (options_.progress && !all_finished()) {
        lock.unlock();  // the workers need the mutex to finish
        options_.progress((std::min)(done_.load(), out_.size()), out_.size());
        lock.lock();
      }
    }
  }

  using difference = typename std::iterator_traits<Iterator>::difference_type;
  const Iterator first_;
  const Work work_;
  std::vector<Result>& out_;
  const batch_options& options_;
  const unsigned threads_;
  const std::size_t chunk_;
  std::atomic<std::size_t> next_{0}, done_{0}, first_failure_;
  std::atomic<bool> cancelled_{false};
  std::exception_ptr failure_;
  std::mutex mutex_;
  std::condition_variable wake_;
  unsigned finished_ = 0;
};

// The batch over any random-access range of throw_start<Real> (std::vector,
// std::array, std::deque, std::span, a C array): nothing is copied.
template <class Real, class Range, class Work>
auto run_batch(const Range& starts, Work work, const batch_options& options) {
  using iterator = decltype(std::begin(starts));
  using element = std::decay_t<decltype(*std::begin(starts))>;
  static_assert(std::is_same<element, throw_start<Real>>::value,
                "spinslide::stop_results takes a range of spinslide::throw_start<Real>, with "
                "Real the value_type of the profile or table");
  static_assert(std::is_base_of<std::random_access_iterator_tag,
                                typename std::iterator_traits<iterator>::iterator_category>::value,
                "spinslide::stop_results needs a random-access range (std::vector, std::array, "
                "std::deque, std::span)");
  using result = std::decay_t<decltype(work(std::declval<const element&>()))>;
  std::vector<result> out(
      static_cast<std::size_t>(std::distance(std::begin(starts), std::end(starts))));
  if (out.empty()) {
    if (options.progress) options.progress(0, 0);
    return out;
  }
  batch_runner<iterator, Work, result>(std::begin(starts), std::move(work), out, options).run();
  return out;
}

}  // namespace detail

/// The stop of every throw in `starts` (a range of throw_start, dimensionless)
/// of a body with `profile` and inertia ratio γ: out[i] is
/// simulate_throw(profile, γ, starts[i].v0, starts[i].omega0), bit for bit,
/// whatever the number of threads.  The throws are spread over
/// `options.threads` threads (0: all cores) in chunks taken as threads free
/// up.  Errors are simulate_throw's: with the default policy the first bad
/// throw in the order of `starts` throws its std::domain_error (the throws
/// after it are not computed); with errno_on_error or ignore_error its result
/// is NaN and the rest are computed.  Allocates the result only.
template <class Profile, class Range>
std::vector<stop_result<typename Profile::value_type>> stop_results(
    const Profile& profile, typename Profile::value_type inertia_ratio, const Range& starts,
    const batch_options& options = {}) {
  static_assert(detail::requires_profile<Profile>());
  using Real = typename Profile::value_type;
  return detail::run_batch<Real>(
      starts,
      [&profile, inertia_ratio](const throw_start<Real>& s) {
        return simulate_throw(profile, inertia_ratio, s.v0, s.omega0);
      },
      options);
}

/// The stop time and distance of every throw in `starts` from a
/// tabulated_throw: out[i] is {table.stop_time(v0, ω0), table.distance(v0,
/// ω0)} of starts[i], bit for bit; threads, order and errors as for the
/// stop_results of a profile.
template <class Profile, class Range>
std::vector<tabulated_stop<typename Profile::value_type>> stop_results(
    const tabulated_throw<Profile>& table, const Range& starts, const batch_options& options = {}) {
  using Real = typename Profile::value_type;
  return detail::run_batch<Real>(
      starts,
      [&table](const throw_start<Real>& s) {
        return tabulated_stop<Real>{table.stop_time(s.v0, s.omega0),
                                    table.distance(s.v0, s.omega0)};
      },
      options);
}

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_BATCH_THROWS_HPP

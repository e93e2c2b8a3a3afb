// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// parallel.h — the array calls of pgloss._core over several threads.
//
// The C core is single-threaded by design (no global state: its users thread it). The binding
// splits one long array call into contiguous blocks of whole units (a unit is one call of the
// C batch over kUnit elements, core.cpp) and runs them on std::threads started for
// the call and joined before it returns (no pool: nothing outlives a call, so fork() is safe).
// Each unit's outputs depend on that unit's inputs only, so the outputs are the same bits for
// any thread count; what a block reports (its first failing element) is merged in block order,
// so the lowest failing index wins, as on one thread.
//
// The calling thread works on blocks too and is the only one that touches Python: it checks
// for signals (Ctrl-C) every kSignalStride elements of its work and, once the blocks are all
// taken, every kWaitPoll while it waits for the others; a signal sets an atomic flag that
// every thread checks before each unit. Workers never call the Python API. An exception in a
// block sets the flag too, and the first in block order is rethrown to the caller after every
// thread has been joined.

#ifndef PGLOSS_PY_PARALLEL_H
#define PGLOSS_PY_PARALLEL_H

#include <pybind11/pybind11.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

namespace pgloss_py {

// Long loops take the GIL back every kSignalStride elements (on the calling thread) so that
// Ctrl-C (SIGINT) gets through: the call stops and raises KeyboardInterrupt.
constexpr std::size_t kSignalStride = std::size_t(1) << 16;

// How often the calling thread, done with its own range, checks for signals while it waits.
constexpr std::chrono::milliseconds kWaitPoll{20};

// The fewest elements worth a thread of their own: below 2 × this an array stays on the calling
// thread. Measured (bench/bench_threads.py, BENCHMARKS.md "Threads"; a 2-core VM): a split call
// costs some 30-80 µs more than its work (starting, waking and joining a thread), and the
// cheapest loops (gloss_from_physical, eval float32 with one material or per element, 4-8 ns an
// element) gain from two threads from 131 072 elements (1.1-1.6×), not yet at 65 536 (0.9×). The
// element-wise scalar functions (vmap, ~40 ns an element) count kScalarCost elements each: they
// gain from 16 384 elements (1.1-1.2×; 1.3-1.6× at 32 768).
constexpr std::size_t kMinPerThread = std::size_t(1) << 16;
constexpr std::size_t kScalarCost = 4;

// The thread count of the array calls: pgloss.set_num_threads (Python validates it). A setting
// of the binding, not of the C core (which has no global state).
inline std::atomic<int> &num_threads() {
    static std::atomic<int> n{1};
    return n;
}

// kMinPerThread, lowered by the tests (to split the shared vectors' short arrays) and the
// benchmark (to measure the crossover): _core._set_min_elements_per_thread.
inline std::atomic<std::size_t> &min_per_thread() {
    static std::atomic<std::size_t> n{kMinPerThread};
    return n;
}

// Shared by the threads of one call.
struct Interrupt {
    std::atomic<bool> stop{false};  // a signal or an exception: every thread stops at its next unit
    bool signalled = false;         // written and read by the calling thread only

    // Calling thread, GIL released: takes the GIL for a moment and checks for signals.
    bool check_signals() {
        pybind11::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) {
            signalled = true;
            stop.store(true, std::memory_order_relaxed);
        }
        return signalled;
    }
    // GIL held: raises the pending KeyboardInterrupt (or the signal handler's exception).
    void raise_if_signalled() const {
        if (signalled) throw pybind11::error_already_set();
    }
};

// A thread's "stop now?" test, called before each unit with the number of elements the
// current block has done: the flag; on the calling thread also the signals, every
// kSignalStride elements of its work (counted across its blocks).
class StopCheck {
  public:
    StopCheck(Interrupt &I, bool caller) : I_(I), caller_(caller) {}
    bool operator()(std::size_t done) {
        if (I_.stop.load(std::memory_order_relaxed)) return true;
        if (!caller_ || offset_ + done < next_) return false;
        next_ = offset_ + done + kSignalStride;
        return I_.check_signals();
    }
    void next_block(std::size_t elements) { offset_ += elements; }

  private:
    Interrupt &I_;
    bool caller_;
    std::size_t offset_ = 0;
    std::size_t next_ = kSignalStride;
};

// The threads the latest split call of this process used (1: not split), for the tests.
inline std::atomic<std::size_t> &last_threads() {
    static std::atomic<std::size_t> n{0};
    return n;
}

// How many threads a call of n elements in `units` units gets; n counts each element's cost
// in units of the cheapest loops' (kScalarCost for a scalar function per element).
inline std::size_t threads_for(std::size_t n, std::size_t units) {
    const auto want = static_cast<std::size_t>(std::max(1, num_threads().load(std::memory_order_relaxed)));
    const std::size_t least = std::max<std::size_t>(1, min_per_thread().load(std::memory_order_relaxed));
    return std::max<std::size_t>(1, std::min({want, units, n / least}));
}

// Blocks per thread: a split call deals its units out in blocks (contiguous ranges of whole
// units), kBlocksPerThread per thread, taken in turn from an atomic counter by whichever thread
// is free. On a shared machine a thread that the OS deschedules then holds up the call by one
// block at most, where equal ranges fixed in advance make the call wait for it (on this
// project's 2-core host with both cores busy with other jobs, gloss_from_physical on 2^22 paints:
// 2 threads with fixed halves took 1.4-2.0× the time of one thread, with blocks 1.05-1.35×).
constexpr std::size_t kBlocksPerThread = 16;

// Runs body(begin, end, stop) -> R over the units [0, units) in contiguous blocks, on up to
// num_threads() threads (the calling thread is one of them); returns the blocks' results in
// block order, so that the first error in index order is the first block's that has one.
// Call with the GIL released. n: the elements, times their cost (threads_for). After it
// returns, call I.raise_if_signalled() with the GIL held.
template <class R, class Body>
std::vector<R> run_ranges(std::size_t n, std::size_t units, Interrupt &I, Body &&body) {
    const std::size_t T = threads_for(n, units);
    last_threads().store(T, std::memory_order_relaxed);
    if (T == 1) {  // today's single-thread loop, on the calling thread
        StopCheck stop(I, true);
        return std::vector<R>{body(std::size_t(0), units, stop)};
    }
    const std::size_t blocks = std::min(units, T * kBlocksPerThread);
    const std::size_t per_unit = units ? (n + units - 1) / units : 0;  // for the signal cadence
    std::vector<R> results(blocks);
    std::vector<std::exception_ptr> errors(blocks);
    std::atomic<std::size_t> next{0};
    auto work = [&](bool caller) {
        StopCheck stop(I, caller);
        for (;;) {
            const std::size_t k = next.fetch_add(1, std::memory_order_relaxed);
            if (k >= blocks || I.stop.load(std::memory_order_relaxed)) return;
            const std::size_t u0 = units * k / blocks, u1 = units * (k + 1) / blocks;
            try {
                results[k] = body(u0, u1, stop);
            } catch (...) {
                errors[k] = std::current_exception();
                I.stop.store(true, std::memory_order_relaxed);
                return;
            }
            stop.next_block((u1 - u0) * per_unit);
        }
    };
    std::mutex mu;
    std::condition_variable cv;
    std::size_t running = 0;
    std::vector<std::thread> pool;
    pool.reserve(T - 1);
    // RAII: every started thread is joined, whatever happens below.
    struct Join {
        std::vector<std::thread> &pool;
        ~Join() {
            for (auto &t : pool)
                if (t.joinable()) t.join();
        }
    } join{pool};
    for (std::size_t k = 1; k < T; ++k) {
        {
            std::lock_guard<std::mutex> lock(mu);
            ++running;
        }
        try {
            pool.emplace_back([&] {
                work(false);
                std::lock_guard<std::mutex> lock(mu);
                --running;
                cv.notify_one();
            });
        } catch (...) {  // std::system_error (no more threads): the threads there are do the work
            std::lock_guard<std::mutex> lock(mu);
            --running;
            break;
        }
    }
    work(true);
    // The other threads finish their last block; the calling thread keeps Ctrl-C alive.
    for (;;) {
        std::unique_lock<std::mutex> lock(mu);
        if (cv.wait_for(lock, kWaitPoll, [&] { return running == 0; })) break;
        lock.unlock();
        if (!I.signalled) I.check_signals();
    }
    for (auto &t : pool) t.join();
    for (auto &e : errors)
        if (e) std::rethrow_exception(e);
    return results;
}

}  // namespace pgloss_py

#endif

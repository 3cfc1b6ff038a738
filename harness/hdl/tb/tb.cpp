// SPDX-License-Identifier: MIT OR Apache-2.0
//
// The Verilator testbench of harness/hdl: reads a published set's inputs with the C
// kit (harness/c/phong_kit.c, linked in), drives every case through the unit
// (tb/top.sv around it) with its set-up, and has the kit write the results CSV
// `check` reads.
//
//   tb INPUTS.csv SETUP.csv RESULTS.csv [--seed N] [--ready-percent P] [--no-gaps]
//      [--extra-bits E] [--truncate] [--eps-n1 EULER_SETUP.csv] [--trace FILE] [--stats]
//      [+verilator+seed+N +verilator+rand+reset+2 ...]
//
// INPUTS.csv is the set's inputs file (vectors/SET-inputs.csv), read by the kit's
// pk_run_f64: the case list and its order come from it. SETUP.csv is `phong-approx
// setup`'s output for the same set: header case,n,p0,dp,t0,ds,q0,dq0,d2q (any column
// order), one row per case, raw signed decimal integers (value = raw * 2^-F), the
// exact set-up rounded once to nearest. Each case of INPUTS.csv is looked up by its id
// in SETUP.csv; a case that is not there, whose n differs, or that comes twice, and a
// row of SETUP.csv with no case in INPUTS.csv, are refused (a stale set-up, or one of
// another set: one line naming the case, exit 2).
//
// The kit reads INPUTS.csv twice. The first pass learns the case list, so that a
// span's set-up can be offered while the previous span's pixels are still leaving the
// unit; in the second, the kit calls the shading function once per case, which runs
// the simulation until that case's out_last and hands the kit its pixels.
// Each case is offered once (in_valid held until in_ready), with 0-3 idle cycles
// after each set-up is taken (none with --no-gaps); out_ready is random (P percent
// high, default 70; below 100, now and then low for up to 40 cycles in a row, and
// rarely for up to 1000), from a fixed seed, so a run is repeatable. A pixel is taken
// on a cycle with out_valid && out_ready, and belongs to the oldest span taken whose
// out_last has not been seen.
//
// RESULTS.csv: `case,pixel,value`, written by the kit, value = raw * 2^-F printed with
// %.17g: a double holds raw * 2^-F exactly when W = M + F <= 53 (run.sh refuses wider
// formats), and %.17g names that double uniquely, so `check --precision f64` reads the
// exact value.
//
// Planted host-side set-up bugs (harness/hdl/run.sh --mutant):
//   --extra-bits E   SETUP.csv holds raw values at F + E fractional bits; they are
//                    brought to F bits here, rounded to nearest (ties away from 0)
//   --truncate       ... floored instead: a set-up truncated where the theorems
//                    assume rounding to nearest (off by up to 2h instead of h)
//   --eps-n1 FILE    corrected Euler's t0 made with eps/(n+1) instead of eps/n:
//                    t0' = di_a - (eps/n) * n/(n+1), di_a from FILE (the plain-Euler
//                    set-up at the same bits, whose t0 is di_a), eps/n = di_a - t0
//
// Exit: 0 results written; 1 the unit broke the handshake (a held pixel changed, a
// pixel with no span in flight) or gave a span another number of pixels than n + 1
// (out_last not with pixel n): one line naming the case; 2 bad input (the kit's
// messages start "phong_kit: "), a set-up that does not match INPUTS.csv, or the cycle
// limit: no handshake for 4096 + 64 W cycles, or a case not done within
// 4096 + 64 W + 16 W (n + 1) cycles of its set-up (the unit never takes the set-up,
// never asserts out_valid, or never out_last): one line naming the case.
//
// --stats prints the cycles per pixel over the set and the range of cycles from a
// set-up taken to its pixel 0 valid (with --ready-percent 100 --no-gaps: the unit's
// own throughput and latency).
//
// --trace FILE writes per case a hash of in_ready and out_valid on every cycle and of
// out_value and out_last on every cycle with out_valid: run.sh compares two runs with
// different random initial values (+verilator+rand+reset+2, built with
// --x-initial unique --x-assign unique) to find X or Z reaching the outputs.

#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "Vunit.h"
#include "phong_kit.h"
#include "verilated.h"

#ifndef PHONG_W
#error "PHONG_W (M + F) is set by run.sh"
#endif
#ifndef PHONG_F
#error "PHONG_F is set by run.sh"
#endif

static const int W = PHONG_W;
static const int F = PHONG_F;
static_assert(W >= 2 && W <= 64, "1 < M + F <= 64");

namespace {

[[noreturn]] void die(int code, const char *fmt, ...) {
    std::fputs("tb: ", stderr);
    va_list ap;
    va_start(ap, fmt);
    std::vfprintf(stderr, fmt, ap);
    va_end(ap);
    std::fputc('\n', stderr);
    std::exit(code);
}

struct Case {
    std::string id;
    uint32_t n = 0;
    int64_t v[7] = {};  // p0, dp, t0, ds, q0, dq0, d2q (raw, F bits after reduce())
    std::vector<int64_t> out;
    uint64_t taken = 0;  // the cycle its set-up was taken
    uint64_t h_ready = 1469598103934665603ull, h_valid = 1469598103934665603ull,
             h_value = 1469598103934665603ull, h_last = 1469598103934665603ull;
};

const char *const kCols[9] = {"case", "n", "p0", "dp", "t0", "ds", "q0", "dq0", "d2q"};

std::vector<std::string> split(const std::string &line) {
    std::vector<std::string> f;
    std::string cur;
    for (char c : line) {
        if (c == ',') {
            f.push_back(cur);
            cur.clear();
        } else if (c != '\r') {
            cur += c;
        }
    }
    f.push_back(cur);
    return f;
}

bool parse_i64(const std::string &s, int64_t *out) {
    if (s.empty()) return false;
    errno = 0;
    char *end = nullptr;
    long long v = std::strtoll(s.c_str(), &end, 10);
    if (errno != 0 || *end != '\0') return false;
    *out = v;
    return true;
}

std::vector<Case> read_setup(const char *path) {
    FILE *f = std::fopen(path, "r");
    if (!f) die(2, "cannot open %s: %s", path, std::strerror(errno));
    std::vector<Case> cases;
    std::map<std::string, bool> seen;
    int col[9];
    char buf[4096];
    int line = 0;
    bool header = false;
    while (std::fgets(buf, sizeof buf, f)) {
        ++line;
        std::string s(buf);
        if (!s.empty() && s.back() != '\n' && !std::feof(f)) die(2, "%s line %d: line too long", path, line);
        while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
        if (s.empty()) continue;
        std::vector<std::string> fs = split(s);
        if (!header) {
            for (int c = 0; c < 9; ++c) {
                col[c] = -1;
                for (size_t i = 0; i < fs.size(); ++i)
                    if (fs[i] == kCols[c]) col[c] = int(i);
                if (col[c] < 0)
                    die(2, "%s line %d: no column %s (the header is case,n,p0,dp,t0,ds,q0,dq0,d2q)",
                        path, line, kCols[c]);
            }
            header = true;
            continue;
        }
        Case c;
        for (int k = 0; k < 9; ++k)
            if (col[k] >= int(fs.size())) die(2, "%s line %d: missing column %s", path, line, kCols[k]);
        c.id = fs[col[0]];
        if (c.id.empty()) die(2, "%s line %d: empty case id", path, line);
        if (seen[c.id]) die(2, "%s line %d: case %s twice", path, line, c.id.c_str());
        seen[c.id] = true;
        int64_t n;
        if (!parse_i64(fs[col[1]], &n) || n < 1 || n > 65535)
            die(2, "%s line %d: case %s: n is not an integer from 1 to 65535 (in_n is 16 bits)", path,
                line, c.id.c_str());
        c.n = uint32_t(n);
        for (int k = 0; k < 7; ++k)
            if (!parse_i64(fs[col[k + 2]], &c.v[k]))
                die(2, "%s line %d: case %s: %s is not a 64-bit integer", path, line, c.id.c_str(),
                    kCols[k + 2]);
        cases.push_back(c);
    }
    if (std::ferror(f)) die(2, "reading %s: %s", path, std::strerror(errno));
    std::fclose(f);
    if (!header) die(2, "%s is empty", path);
    if (cases.empty()) die(2, "%s has no cases", path);
    return cases;
}

// x / 2^e rounded to nearest, ties away from zero, or floored.
__int128 reduce(__int128 x, int e, bool truncate) {
    if (e == 0) return x;
    if (truncate) return x >> e;  // arithmetic: floor
    const __int128 half = __int128(1) << (e - 1);
    return x >= 0 ? (x + half) >> e : -((-x + half) >> e);
}

// a / b rounded to nearest, ties away from zero (b > 0).
__int128 div_nearest(__int128 a, __int128 b) {
    return a >= 0 ? (2 * a + b) / (2 * b) : -((-2 * a + b) / (2 * b));
}

uint64_t fnv(uint64_t h, uint64_t v) {
    for (int i = 0; i < 8; ++i) {
        h ^= (v >> (8 * i)) & 0xff;
        h *= 1099511628211ull;
    }
    return h;
}

struct Rng {
    uint64_t s;
    uint64_t next() {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        return s;
    }
    uint32_t below(uint32_t k) { return uint32_t(next() % k); }
};

uint64_t raw_bits(int64_t v) {
    const uint64_t mask = W == 64 ? ~0ull : ((1ull << W) - 1);
    return uint64_t(v) & mask;
}

int64_t sign_extend(uint64_t x) {
    if (W == 64) return int64_t(x);
    const uint64_t mask = (1ull << W) - 1;
    x &= mask;
    if (x >> (W - 1)) x |= ~mask;
    return int64_t(x);
}


// The first pass over the inputs: the case list, each case with its set-up.
struct Plan {
    const char *inputs_path, *setup_path;
    const std::vector<Case> *setup;
    std::map<std::string, size_t> index;  // id -> row of *setup
    std::vector<bool> used;               // rows of *setup with a case in the inputs
    std::vector<Case> cases;              // in the inputs' order
};

int plan_case(const pk_case_f64 *c, double *out, void *user) {
    Plan &p = *static_cast<Plan *>(user);
    auto it = p.index.find(c->id);
    if (it == p.index.end())
        die(2, "case %s of %s is not in the set-up %s (a stale set-up, or one of another set)", c->id,
            p.inputs_path, p.setup_path);
    const Case &s = (*p.setup)[it->second];
    if (p.used[it->second]) die(2, "case %s is twice in %s", c->id, p.inputs_path);
    if (long(s.n) != c->n)
        die(2, "case %s: n = %ld in %s, but n = %u in the set-up %s (a stale set-up, or one of another set)",
            c->id, c->n, p.inputs_path, s.n, p.setup_path);
    p.used[it->second] = true;
    p.cases.push_back(s);
    for (long i = 0; i <= c->n; ++i) out[i] = 0;  // this pass's results are not kept
    return 0;
}

// The second pass: the kit's shading function, one case at a time.
struct Drive {
    const char *inputs_path;
    std::vector<Case> *cases;
    std::function<void(size_t)> run_until;  // simulates until case k's out_last
    size_t k;                               // the next case
};

int drive_case(const pk_case_f64 *c, double *out, void *user) {
    Drive &d = *static_cast<Drive *>(user);
    if (d.k >= d.cases->size() || (*d.cases)[d.k].id != c->id || long((*d.cases)[d.k].n) != c->n)
        die(2, "%s changed while it was read (case %s)", d.inputs_path, c->id);
    const Case &s = (*d.cases)[d.k];
    d.run_until(d.k++);
    const size_t pixels = s.out.size();  // >= 1: out_last comes with a pixel
    if (pixels < size_t(s.n) + 1)
        die(1, "case %s has no value for pixel %zu: out_last came with pixel %zu (pixels 0..=%u)", s.id.c_str(),
            pixels, pixels - 1, s.n);
    if (pixels > size_t(s.n) + 1)
        die(1, "case %s: pixel %u is out of range (pixels 0..=%u): out_last not with pixel %u", s.id.c_str(),
            s.n + 1, s.n, s.n);
    for (size_t i = 0; i < pixels; ++i) out[i] = std::ldexp(double(s.out[i]), -F);
    return 0;
}

}  // namespace

int main(int argc, char **argv) {
    const char *inputs_path = nullptr, *setup_path = nullptr, *results_path = nullptr, *euler_path = nullptr,
               *trace_path = nullptr;
    uint64_t seed = 1;
    int ready_percent = 70, extra = 0;
    bool truncate = false, stats = false, gaps = true;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&](const char *what) -> const char * {
            if (i + 1 >= argc) die(2, "%s needs %s", a.c_str(), what);
            return argv[++i];
        };
        if (a[0] == '+') continue;  // Verilator's +verilator+... arguments
        if (a == "--seed") seed = std::strtoull(value("a number"), nullptr, 10);
        else if (a == "--ready-percent") ready_percent = std::atoi(value("a percentage"));
        else if (a == "--extra-bits") extra = std::atoi(value("a number of bits"));
        else if (a == "--truncate") truncate = true;
        else if (a == "--no-gaps") gaps = false;
        else if (a == "--eps-n1") euler_path = value("the plain-Euler set-up CSV");
        else if (a == "--trace") trace_path = value("a file");
        else if (a == "--stats") stats = true;
        else if (a[0] == '-') die(2, "unknown option %s", a.c_str());
        else if (!inputs_path) inputs_path = argv[i];
        else if (!setup_path) setup_path = argv[i];
        else if (!results_path) results_path = argv[i];
        else die(2, "one inputs file, one set-up file and one results file");
    }
    if (!inputs_path || !setup_path || !results_path)
        die(2, "usage: tb INPUTS.csv SETUP.csv RESULTS.csv [--seed N] [--ready-percent P] [--no-gaps] "
               "[--extra-bits E] [--truncate] [--eps-n1 EULER_SETUP.csv] [--trace FILE] [--stats]");
    if (ready_percent < 1 || ready_percent > 100) die(2, "--ready-percent takes 1 to 100");
    if (extra < 0 || extra > 16) die(2, "--extra-bits takes 0 to 16");
    if (seed == 0) seed = 1;

    // The case list: the inputs' cases, in their order, each with its set-up.
    const std::vector<Case> setup = read_setup(setup_path);
    Plan plan{inputs_path, setup_path, &setup, {}, std::vector<bool>(setup.size(), false), {}};
    for (size_t i = 0; i < setup.size(); ++i) plan.index[setup[i].id] = i;
    FILE *in = std::fopen(inputs_path, "r");
    if (!in) die(2, "cannot open %s: %s", inputs_path, std::strerror(errno));
    FILE *discard = std::fopen("/dev/null", "w");
    if (!discard) die(2, "cannot open /dev/null: %s", std::strerror(errno));
    if (pk_run_f64(in, inputs_path, discard, 0, plan_case, &plan) != PK_OK) return 2;  // the kit said why
    std::fclose(discard);
    for (size_t i = 0; i < setup.size(); ++i)
        if (!plan.used[i])
            die(2, "case %s of the set-up %s is not in %s (a stale set-up, or one of another set)",
                setup[i].id.c_str(), setup_path, inputs_path);
    std::vector<Case> cases = std::move(plan.cases);

    std::map<std::string, int64_t> di_a;
    if (euler_path) {
        for (const Case &c : read_setup(euler_path)) di_a[c.id] = c.v[2];
    }
    const __int128 lo = -(__int128(1) << (W - 1)), hi = (__int128(1) << (W - 1)) - 1;
    for (Case &c : cases) {
        __int128 v[7];
        for (int k = 0; k < 7; ++k) v[k] = c.v[k];
        if (euler_path) {
            auto it = di_a.find(c.id);
            if (it == di_a.end()) die(2, "case %s is not in %s", c.id.c_str(), euler_path);
            const __int128 eps_n = __int128(it->second) - v[2];  // eps/n = di_a - t0
            v[2] = __int128(it->second) - div_nearest(eps_n * c.n, __int128(c.n) + 1);
        }
        for (int k = 0; k < 7; ++k) {
            v[k] = reduce(v[k], extra, truncate);
            if (v[k] < lo || v[k] > hi)
                die(2, "case %s: %s does not fit %d bits", c.id.c_str(), kCols[k + 2], W);
            c.v[k] = int64_t(v[k]);
        }
    }

    auto ctx = std::make_unique<VerilatedContext>();
    ctx->commandArgs(argc, argv);
    auto top = std::make_unique<Vunit>(ctx.get());
    Rng rng{seed * 0x9E3779B97F4A7C15ull};

    const uint64_t stall_limit = 4096 + 64 * uint64_t(W);
    uint64_t cycle = 0;
    auto set_inputs = [&](bool valid, const Case *c) {
        top->in_valid = valid;
        if (c) {
            top->in_n = uint16_t(c->n);
            top->in_p0 = static_cast<std::remove_reference<decltype(top->in_p0)>::type>(raw_bits(c->v[0]));
            top->in_dp = static_cast<std::remove_reference<decltype(top->in_dp)>::type>(raw_bits(c->v[1]));
            top->in_t0 = static_cast<std::remove_reference<decltype(top->in_t0)>::type>(raw_bits(c->v[2]));
            top->in_ds = static_cast<std::remove_reference<decltype(top->in_ds)>::type>(raw_bits(c->v[3]));
            top->in_q0 = static_cast<std::remove_reference<decltype(top->in_q0)>::type>(raw_bits(c->v[4]));
            top->in_dq0 = static_cast<std::remove_reference<decltype(top->in_dq0)>::type>(raw_bits(c->v[5]));
            top->in_d2q = static_cast<std::remove_reference<decltype(top->in_d2q)>::type>(raw_bits(c->v[6]));
        }
    };

    // Reset: four cycles.
    top->clk = 0;
    top->rst = 1;
    top->out_ready = 0;
    set_inputs(false, nullptr);
    top->eval();
    for (int i = 0; i < 4; ++i) {
        top->clk = 1;
        top->eval();
        top->clk = 0;
        top->eval();
    }
    top->rst = 0;

    size_t next = 0;          // the next case to offer
    std::deque<size_t> busy;  // cases taken, pixels still coming
    std::vector<bool> done(cases.size(), false);  // out_last seen
    uint32_t gap = gaps ? rng.below(4) : 0, hold_low = 0;
    uint64_t since = 0;  // cycles since the last handshake
    bool held = false;   // last cycle: out_valid && !out_ready
    int64_t held_value = 0;
    bool held_last = false;
    uint64_t first_latency_max = 0, first_latency_min = UINT64_MAX;
    std::vector<uint64_t> first_seen(cases.size(), 0);

    // The simulation, cycle by cycle, until case k's out_last. The next case's set-up
    // is offered (after its idle cycles) whether or not earlier spans are still
    // leaving the unit: the unit takes it when it is ready to.
    auto run_until = [&](size_t k) {
        while (!done[k]) {
            // Inputs for this cycle (clk low).
            const bool offer = next < cases.size() && gap == 0;
            set_inputs(offer, offer ? &cases[next] : nullptr);
            bool ready;
            if (hold_low > 0) {
                --hold_low;
                ready = false;
            } else if (ready_percent < 100 && rng.below(64) == 0) {
                hold_low = rng.below(64) == 0 ? 1 + rng.below(1000) : 1 + rng.below(40);
                ready = false;
            } else {
                ready = int(rng.below(100)) < ready_percent;
            }
            top->out_ready = ready;
            top->eval();

            const bool in_ready = top->in_ready, out_valid = top->out_valid;
            const int64_t value = sign_extend(uint64_t(top->out_value));
            const bool last = top->out_last;
            const size_t cur = !busy.empty() ? busy.front() : next;
            if (cur < cases.size()) {
                Case &c = cases[cur];
                c.h_ready = fnv(c.h_ready, in_ready);
                c.h_valid = fnv(c.h_valid, out_valid);
                if (out_valid) {
                    c.h_value = fnv(c.h_value, uint64_t(value));
                    c.h_last = fnv(c.h_last, last);
                }
            }
            if (held) {
                if (!out_valid || value != held_value || last != held_last) {
                    const Case &c = cases[busy.empty() ? 0 : busy.front()];
                    die(1, "case %s, pixel %zu: %s while out_valid was high and out_ready low (a pixel must "
                           "be held until taken)",
                        c.id.c_str(), c.out.size(),
                        !out_valid ? "out_valid fell" : value != held_value ? "out_value changed" : "out_last changed");
                }
            }
            const bool in_fire = offer && in_ready;
            const bool out_fire = out_valid && ready;
            held = out_valid && !ready;
            held_value = value;
            held_last = last;

            if (out_valid && !busy.empty()) {
                const size_t b = busy.front();
                if (cases[b].out.empty() && first_seen[b] == 0) first_seen[b] = cycle + 1;
            }
            if (out_fire) {
                if (busy.empty())
                    die(1, "a pixel left the unit with no span in flight (after case %s)",
                        next ? cases[next - 1].id.c_str() : "none");
                Case &c = cases[busy.front()];
                c.out.push_back(value);
                if (last) {
                    done[busy.front()] = true;
                    busy.pop_front();
                }
            }
            if (in_fire) {
                cases[next].taken = cycle;
                busy.push_back(next);
                ++next;
                gap = gaps ? rng.below(4) : 0;
            } else if (gap > 0 && next < cases.size()) {
                --gap;
            }

            // The clock edge.
            top->clk = 1;
            top->eval();
            top->clk = 0;
            top->eval();
            ++cycle;

            since = (in_fire || out_fire) ? 0 : since + 1;
            if (since > stall_limit) {
                if (!busy.empty()) {
                    const Case &c = cases[busy.front()];
                    die(2, "case %s: no pixel for %" PRIu64 " cycles after %s (out_valid %s): the cycle limit",
                        c.id.c_str(), stall_limit,
                        c.out.empty() ? "its set-up was taken" : ("pixel " + std::to_string(c.out.size() - 1)).c_str(),
                        out_valid ? "high, but out_ready was low" : "stayed low");
                }
                die(2, "case %s: the set-up was not taken for %" PRIu64 " cycles (in_ready stayed low): the cycle limit",
                    cases[next].id.c_str(), stall_limit);
            }
            if (!busy.empty()) {
                const Case &c = cases[busy.front()];
                const uint64_t limit = stall_limit + 16 * uint64_t(W) * (uint64_t(c.n) + 1);
                if (cycle - c.taken > limit)
                    die(2, "case %s: not done %" PRIu64 " cycles after its set-up was taken (%zu pixels out of %u, "
                           "no out_last): the cycle limit",
                        c.id.c_str(), limit, c.out.size(), c.n + 1);
            }
        }
    };

    // The results: the kit reads the inputs again and writes each case's pixels.
    FILE *out = std::fopen(results_path, "w");
    if (!out) die(2, "cannot write %s: %s", results_path, std::strerror(errno));
    std::rewind(in);
    Drive drive{inputs_path, &cases, run_until, 0};
    if (pk_run_f64(in, inputs_path, out, 0, drive_case, &drive) != PK_OK) return 2;  // the kit said why
    std::fclose(in);
    if (drive.k != cases.size()) die(2, "%s changed while it was read", inputs_path);
    if (std::fclose(out) != 0) die(2, "writing %s: %s", results_path, std::strerror(errno));
    top->final();

    if (trace_path) {
        FILE *t = std::fopen(trace_path, "w");
        if (!t) die(2, "cannot write %s: %s", trace_path, std::strerror(errno));
        std::fputs("case,in_ready,out_valid,out_value,out_last\n", t);
        for (const Case &c : cases)
            std::fprintf(t, "%s,%016" PRIx64 ",%016" PRIx64 ",%016" PRIx64 ",%016" PRIx64 "\n", c.id.c_str(),
                         c.h_ready, c.h_valid, c.h_value, c.h_last);
        if (std::fclose(t) != 0) die(2, "writing %s: %s", trace_path, std::strerror(errno));
    }
    if (stats) {
        uint64_t pixels = 0;
        for (size_t i = 0; i < cases.size(); ++i) {
            pixels += cases[i].out.size();
            if (first_seen[i]) {
                const uint64_t l = first_seen[i] - cases[i].taken - 1;
                if (l > first_latency_max) first_latency_max = l;
                if (l < first_latency_min) first_latency_min = l;
            }
        }
        std::fprintf(stderr,
                     "tb: %zu cases, %" PRIu64 " pixels in %" PRIu64 " cycles (%.2f cycles a pixel); pixel 0 valid %" PRIu64
                     " to %" PRIu64 " cycles after its set-up was taken\n",
                     cases.size(), pixels, cycle, double(cycle) / double(pixels), first_latency_min, first_latency_max);
    }
    return 0;
}

#!/usr/bin/env python3
"""Groups a flat `perf` profile of bfemp's explicit step into its phases.

Usage (see doc/performance.md):

  perf record -e cpu-clock -F 1000 -D 1000 -o case0.data \\
      build/benchmarks/explicit_throughput --case 0 --profile-steps 300
  python3 benchmarks/profile_breakdown.py case0.data

-D (ms) skips the set-up; --profile-steps runs bfemp steps on one thread
only. Symbols of the set-up and of the hand-written loop, should any be in
the samples, are counted apart and left out of the percentages. The groups
are by function name, so they follow the library as it is today: check the
"other" lines after a library change.
"""

import re
import subprocess
import sys

EXCLUDED = ("set-up / hand-written loop (left out)",
            r"HandLoop|BodySampler|Shape|ParameterHandler|DoFHandler|"
            r"distribute|copy_to_loop|compare<|check_state|one_step_crossings|"
            r"_dl_|do_lookup|check_match|GridGenerator|Patterns|FESystem|"
            r"BackgroundGrid<.>::BackgroundGrid|Vortex|read_scene")

GROUPS = [
    ("P2G: scatter loop", r"ParticleGridTransfer<.>::scatter"),
    ("P2G: neo-Hookean P(F), log", r"NeoHookean|ieee754_log|^log@"),
    ("P2G+G2P: KernelStencil::reinit (weights)", r"KernelStencil"),
    ("G2P: gather loop", r"ParticleGridTransfer<.>::gather"),
    ("particles_in_cell (deal.II, every loop)",
     r"ParticleHandler<., .>::particles_in_cell"),
    ("update_cells: per-particle pass (parallel)",
     r"update_cells\(\)::\{lambda|reference_location|stencil_inside|"
     r"lattice_cell|TriaAccessor<.*center|locally_owned_subdomain|n_vertices"),
    ("update_cells: update_cached_numbers (serial)", r"update_cached_numbers"),
    ("update_cells: remove/insert movers, stripes, re-order (serial)",
     r"insert_particle|remove_particle|clear_particles|_List_|__list_|"
     r"store_in_loop_order|introsort|insertion_sort|update_cells\s*$|"
     r"rebuild_stripes|n_particles_in_cell|reset_particle_container|"
     r"PropertyPool|BackgroundGrid<.>::cell\s*$|_M_default_append|"
     r"_M_range_insert|_M_realloc_insert|Moved"),
    ("malloc/free/memcpy (update_cells)",
     r"malloc|_int_free|cfree|unlink_chunk|memmove|memcpy|operator new|"
     r"operator delete|^free$"),
    ("grid: zeroing, velocity update, walls",
     r"GridBoundaries|BoundaryCondition|memset|ExplicitMPM|_M_fill_assign"),
    ("TBB, kernel", r"tbb::|^0x|execute_and_wait|raw_spin|finish_task|irq|"
     r"page_fault|clear_page|__schedule|folio|do_anonymous_page"),
]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    report = subprocess.run(
        ["perf", "report", "-i", sys.argv[1], "--no-children", "--sort",
         "symbol", "--stdio", "-g", "none", "--percent-limit", "0.01"],
        capture_output=True, text=True, check=True).stdout
    rows = []
    for line in report.splitlines():
        match = re.match(r"\s+([\d.]+)%\s+\[(.)\]\s+(.*)$", line)
        if match:
            # perf may append empty "-  -" columns after the name
            symbol = re.sub(r"(\s+-)+\s*$", "", match.group(3)).strip()
            rows.append((float(match.group(1)), symbol))
    excluded, totals, others = 0., {name: 0. for name, _ in GROUPS}, []
    for percent, symbol in rows:
        if re.search(EXCLUDED[1], symbol):
            excluded += percent
            continue
        for name, pattern in GROUPS:
            if re.search(pattern, symbol):
                totals[name] += percent
                break
        else:
            others.append((percent, symbol))
    step = sum(totals.values()) + sum(p for p, _ in others)
    print(f"{'phase':64s} {'% of step':>9s}")
    for name, _ in GROUPS:
        print(f"{name:64s} {100 * totals[name] / step:9.1f}")
    print(f"{'other':64s} {100 * sum(p for p, _ in others) / step:9.1f}")
    print(f"({EXCLUDED[0]}: {excluded:.1f} % of all samples)")
    for percent, symbol in sorted(others, reverse=True)[:5]:
        print(f"  other: {percent:5.2f} % {symbol[:100]}")


if __name__ == "__main__":
    main()

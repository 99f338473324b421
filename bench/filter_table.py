"""filter_table: the filters and chains the quality study (bench/quality_study)
and the speed report (bench/speed_table) measure, as data.

One Entry per filter or chain: its name in the tables, its family (one gallery
section per family), the mcdtool arguments that run it, and OpenImageIO's
nearest operations for the speed report. The window filters (those taking one
window size) come from the library's Python bindings (window_filters): a new
one is measured without an edit here. To add another filter or chain, add an
Entry to entries(); an entry whose mcdtool commands the mcdtool being measured
does not have yet is left out (and named) by both scripts.
"""
import importlib
import os
import re
import subprocess
import sys
from dataclasses import dataclass, field

# The window sides every window filter is measured at (the report's 3 and 7).
SIZES = (3, 7)


@dataclass(frozen=True)
class Entry:
    name: str             # row name in the tables, e.g. "object_median 7"
    family: str           # gallery section, e.g. "object"
    args: tuple           # mcdtool arguments, e.g. ("--object-median", "7")
    # OpenImageIO's nearest operations, run in turn: ("median", SIZE) is
    # ImageBufAlgo.median_filter, ("gaussian", SIZE) convolve with a gaussian
    # kernel of that width; empty when OIIO has nothing comparable.
    oiio: tuple = field(default=())

    def commands(self):
        """The mcdtool commands (--name) this entry calls."""
        return [a for a in self.args if re.fullmatch(r"--[a-z][a-z0-9-]*", a)]


# OpenImageIO's nearest operation to each window reduction (the last word of
# a window filter's name), in the order the tables list a family's filters; a
# reduction not here has no OIIO counterpart and comes last.
NEAREST_OIIO = {"mean": "gaussian", "median": "median", "gaussian": "gaussian"}
# The family of the window filters whose name is one word (mean, median, ...).
PLAIN_FAMILY = "simple"

# The report's best chain, the subject of its headline claim.
BEST_CHAIN = Entry("object_median 7 + gaussian 3", "chain",
                   ("--object-median", "7", "--gaussian", "3"),
                   (("median", 7), ("gaussian", 3)))



def parameters(function):
    """The parameter names of a bound library function, from the signature
    pybind11 puts on the first line of its docstring (none if overloaded)."""
    signature = re.match(r"\w+\((.*)\) -> ", function.__doc__ or "")
    return re.findall(r"(?:^|, )(\w+):", signature.group(1)) if signature else []


def reduction_rank(name):
    """Where the window filter `name` comes in its family: in NEAREST_OIIO's
    order by its last word, a reduction not there last."""
    reductions = list(NEAREST_OIIO)
    reduction = name.split("_")[-1]
    return reductions.index(reduction) if reduction in reductions else len(reductions)


def window_filters(library):
    """(family, function, OIIO's nearest operation or None) of every filter of
    `library` (the mcdenoise module) that takes one window size: a `size`
    parameter and no `guides` (the feature filters' window is not their only
    parameter). The family is the name's first word (PLAIN_FAMILY for a
    one-word name); families in the bindings' order, then NEAREST_OIIO's."""
    found = []
    for name, function in vars(library).items():
        params = parameters(function) if callable(function) else []
        if "size" in params and "guides" not in params:
            words = name.split("_")
            family = words[0] if len(words) > 1 else PLAIN_FAMILY
            found.append((family, name, NEAREST_OIIO.get(words[-1])))
    families = list(dict.fromkeys(family for family, _, _ in found))
    return sorted(found, key=lambda row: (families.index(row[0]), reduction_rank(row[1])))


def entries(library):
    """Every filter and chain measured: the window filters of `library` (the
    mcdenoise module) at every size of SIZES, then the others."""
    return [
        Entry(f"{function} {size}", family, ("--" + function.replace("_", "-"), str(size)),
              ((oiio, size),) if oiio else ())
        for family, function, oiio in window_filters(library) for size in SIZES
    ] + [
        # The report's front-focus example: 10 levels, sides 1, 3, ..., 19.
        Entry("dof 10 0", "dof", ("--dof", "10", "0")),
        BEST_CHAIN,
        # The chain on albedo-demodulated colour: the answer to medians erasing texture.
        Entry("demodulate + object_median 7 + gaussian 3 + remodulate", "chain",
              ("--demodulate", *BEST_CHAIN.args, "--remodulate"), BEST_CHAIN.oiio),
        Entry("clamp_fireflies 2 + object_median 7 + gaussian 3", "chain",
              ("--clamp-fireflies", "2", *BEST_CHAIN.args), BEST_CHAIN.oiio),
    ] + [
        # Beyond the report (issue 8): feature-guided filters, guides as present.
        Entry(f"cross_bilateral {size}", "feature", ("--cross-bilateral", str(size)),
              (("gaussian", size),))
        for size in SIZES
    ] + [
        # a-trous: ITERATIONS passes of a 5x5 kernel with step 2^i (3: 29x29
        # reach), 3 and the library's default (5).
        Entry(f"atrous {n}", "feature", ("--atrous", str(n)))
        for n in (3, library.default_atrous_iterations)
    ] + [
        # nlmeans: SEARCH_RADIUS 3 and the library's default (7): search windows
        # 7x7 and 15x15, the default 3x3 patches.
        Entry(f"nlmeans {r}", "feature", ("--nlmeans", str(r)))
        for r in (3, library.default_nlmeans_search_radius)
    ] + [
        Entry("denoise", "preset", ("--denoise",)),
    ]


# Extra gallery sections: a file name, a title and the entries shown side by
# side at the headline's spp (those that exist), between the raw render at the
# headline's high spp and the reference.
COMPARISONS = [
    ("headline", "the report's best chain and the denoise preset against many samples",
     [BEST_CHAIN.name, "denoise"]),
]


def mcdtool_commands(mcdtool):
    """The set of commands (--name) `mcdtool --help` lists."""
    text = subprocess.run([mcdtool, "--help"], check=True, capture_output=True,
                          text=True).stdout
    return set(re.findall(r"(?<![\w-])--[a-z][a-z0-9-]*", text))


def library(build):
    """The mcdenoise module built in `build` (its python/ put on sys.path)."""
    path = os.path.join(build, "python")
    if path not in sys.path:
        sys.path.insert(0, path)
    try:
        return importlib.import_module("mcdenoise")
    except ImportError as error:
        sys.exit(f"filter_table: no mcdenoise module in {path} (build with the Python "
                 f"bindings): {error}")


def available(build):
    """(entries the mcdtool of `build` can run, names of those it cannot)."""
    commands = mcdtool_commands(os.path.join(build, "bin", "mcdtool"))
    every = entries(library(build))
    runnable = [e for e in every if set(e.commands()) <= commands]
    missing = [e.name for e in every if not set(e.commands()) <= commands]
    return runnable, missing

"""filter_table: the filters and chains the quality study (bench/quality_study)
and the speed report (bench/speed_table) measure, as data.

One Entry per filter or chain: its name in the tables, its family (one gallery
section per family), the mcdtool arguments that run it, and OpenImageIO's
nearest operations for the speed report. To add a filter, add an Entry (or a
row of WINDOW_FILTERS); an entry whose mcdtool commands the mcdtool being
measured does not have yet is left out (and named) by both scripts.
"""
import re
import subprocess
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


# (family, library function, OIIO's nearest operation) of every filter that
# takes one window size; each is measured at every size of SIZES.
WINDOW_FILTERS = [
    ("simple", "mean", "gaussian"),
    ("simple", "median", "median"),
    ("simple", "gaussian", "gaussian"),
    ("object", "object_mean", "gaussian"),
    ("object", "object_median", "median"),
    ("object", "object_gaussian", "gaussian"),
    ("brdf", "brdf_mean", "gaussian"),
    ("brdf", "brdf_median", "median"),
    ("brdf", "brdf_gaussian", "gaussian"),
    ("normal", "normal_mean", "gaussian"),
    ("normal", "normal_gaussian", "gaussian"),
]

# The report's best chain, the subject of its headline claim.
BEST_CHAIN = Entry("object_median 7 + gaussian 3", "chain",
                   ("--object-median", "7", "--gaussian", "3"),
                   (("median", 7), ("gaussian", 3)))

ENTRIES = [
    Entry(f"{function} {size}", family, ("--" + function.replace("_", "-"), str(size)),
          ((oiio, size),))
    for family, function, oiio in WINDOW_FILTERS for size in SIZES
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
    # a-trous: ITERATIONS passes of a 5x5 kernel with step 2^i (3: 29x29 reach).
    Entry(f"atrous {n}", "feature", ("--atrous", str(n))) for n in (3, 5)
] + [
    # nlmeans: SEARCH_RADIUS 3 and 7 (search windows 7x7 and 15x15, 3x3 patches).
    Entry(f"nlmeans {r}", "feature", ("--nlmeans", str(r))) for r in (3, 7)
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


def available(mcdtool):
    """(entries mcdtool can run, names of those it cannot)."""
    commands = mcdtool_commands(mcdtool)
    runnable = [e for e in ENTRIES if set(e.commands()) <= commands]
    missing = [e.name for e in ENTRIES if not set(e.commands()) <= commands]
    return runnable, missing

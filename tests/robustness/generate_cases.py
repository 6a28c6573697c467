#!/usr/bin/python3
"""Generate the robustness suite: bad inputs that diskimpact must refuse.

usage: generate_cases.py OUTPUT_DIR [--gmsh PATH]

Writes one folder per case into OUTPUT_DIR (the parameter file, normally
case.prm, and its auxiliary files: meshes, included files) and
OUTPUT_DIR/manifest.json, a list of records

    {"name", "directory", "prm", "ranks", "expect", "what"}

("directory" relative to OUTPUT_DIR, "prm" relative to "directory"). Every
case must make diskimpact stop with exit code 1, one line
"diskimpact: error: ..." on standard error containing "expect" (compared
case-insensitively by run_cases.py), and nothing written. Each generated .prm
starts with a comment saying what is wrong (except the files whose defect is
their whole content: empty, binary junk) and sets
'Output directory = output/case'.

The cases start from small, valid versions of the shipped parameter files
(params/*.prm, tests/regression/*.prm), one per task, and change one thing:
the .prm syntax, one value of one entry (malformed numbers, values out of
their documented range, bad lists), the mesh file (made with gmsh from
meshes/disk.geo or written by hand), or a combination of entries that the
task cannot run with. About 20 cases are repeated on 2 MPI ranks.
"""
import argparse
import copy
import json
import random
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

OUTPUT_DIRECTORY = "output/case"
DISK_GEO = Path(__file__).resolve().parents[2] / "meshes" / "disk.geo"

# --------------------------------------------------------------------------
# Parameter files
# --------------------------------------------------------------------------


class Prm:
    """A parameter file as ordered subsections of ordered entries; the top
    level is the subsection None."""

    def __init__(self, top, sections):
        self.sections = {None: dict(top)}
        for name, entries in sections:
            self.sections[name] = dict(entries)

    def set(self, path, value):
        """Set 'Section/Entry' (or a top-level 'Entry') to value."""
        section, entry = split_path(path)
        self.sections.setdefault(section, {})[entry] = value
        return self

    def render(self, comment):
        """The .prm text, starting with the comment lines."""
        lines = ["# " + line for line in comment.splitlines()]
        lines += [f"set {k} = {v}".rstrip() for k, v in self.sections[None].items()]
        for name, entries in self.sections.items():
            if name is None:
                continue
            lines += ["", f"subsection {name}"]
            lines += [f"  set {k} = {v}".rstrip() for k, v in entries.items()]
            lines.append("end")
        return "\n".join(lines) + "\n"


def split_path(path):
    """'Geometry/Radius' -> ('Geometry', 'Radius'); 'Task' -> (None, 'Task')."""
    if "/" in path:
        section, entry = path.split("/", 1)
        return section, entry
    return None, path


def top(task):
    return [("Task", task), ("Output directory", OUTPUT_DIRECTORY)]


# Small, fast, valid versions of the shipped parameter files, one per task
# (and per variant a case needs, e.g. the exponential wall law).
IMPACT_SECTIONS = [
    ("Geometry", [("Domain", "half disk"), ("Global refinements", "1")]),
    ("Material", [("Plane model", "plane stress"), ("Poisson ratio", "0.33")]),
    ("Finite element", [("Degree", "2")]),
    ("Contact", [("Penalty factor", "100")]),
    ("Impact", [("Velocity", "0.05"), ("Elements across contact", "6"),
                ("Grading", "0.6"), ("Output interval", "0"),
                ("Number of projected modes", "0")]),
    ("Time stepping", [("Scheme", "energy conserving"),
                       ("Time step fraction", "0.05")]),
]

BASES = {
    # params/modal.prm, coarser
    "modal": (top("modal analysis"), [
        ("Geometry", [("Radius", "1"), ("Domain", "full disk"),
                      ("Global refinements", "1")]),
        ("Material", [("Plane model", "plane strain"), ("Young modulus", "1"),
                      ("Poisson ratio", "0.3"), ("Density", "1")]),
        ("Finite element", [("Degree", "2")]),
        ("Modal analysis", [("Number of modes", "5")]),
    ]),
    # params/modal_convergence.prm, fewer levels
    "modalconv": (top("modal convergence"), [
        ("Geometry", [("Domain", "half disk")]),
        ("Material", [("Plane model", "plane strain"), ("Poisson ratio", "0.3")]),
        ("Modal convergence", [("Degrees", "1, 2"),
                               ("Refinement levels", "1, 2"),
                               ("Modes compared", "3")]),
    ]),
    # params/quasistatic_contact.prm, tests/regression/contact_two_loads.prm
    "quasistatic": (top("quasistatic contact"), [
        ("Geometry", [("Domain", "half disk"), ("Global refinements", "1")]),
        ("Material", [("Plane model", "plane strain"), ("Poisson ratio", "0.3")]),
        ("Finite element", [("Degree", "2")]),
        ("Contact", [("Penalty factor", "400"), ("Wall point", "0, 0"),
                     ("Wall normal", "1, 0")]),
        ("Quasistatic contact", [("Loads", "1e-3"),
                                 ("Elements across contact", "10"),
                                 ("Grading", "0.3")]),
    ]),
    # tests/regression/impact_short.prm, coarser
    "impact": (top("impact"), IMPACT_SECTIONS),
    # params/impact_convergence.prm, tests/regression/impact_convergence_small.prm
    "impactconv": (top("impact convergence"), IMPACT_SECTIONS + [
        ("Impact convergence", [("Mesh levels", "2"), ("Time step levels", "1"),
                                ("Penalty levels", "1")]),
    ]),
    # params/sweep.prm, tests/regression/sweep_consistency.prm
    "sweep": (top("sweep"), IMPACT_SECTIONS + [
        ("Impact", [("Velocities", "0.05"), ("Convergence study per point", "false"),
                    ("Elements across contact", "6"), ("Grading", "0.6"),
                    ("Output interval", "0"), ("Number of projected modes", "0")]),
    ]),
    # params/reference_*.prm
    "reference": (top("reference models"), [
        ("Material", [("Plane model", "plane stress"), ("Poisson ratio", "0.33")]),
        ("Reference models", [("Model", "disk"), ("Velocities", "0.01, 0.05"),
                              ("Relaxation times", "0.05")]),
    ]),
    # params/modal_expansion.prm, tests/regression/modal_expansion_small.prm
    "expansion": (top("modal expansion impact"), [
        ("Material", [("Plane model", "plane stress"), ("Poisson ratio", "0.33")]),
        ("Modal expansion", [("Velocities", "0.1"),
                             ("Potential stiffnesses", "100"),
                             ("Mode counts", "20, 40"),
                             ("Steps per period", "40"),
                             ("Number of listed modes", "3")]),
    ]),
}

# Variants: a base plus the settings that make an entry matter.
VARIANTS = {
    "impact_exponential": ("impact", {"Contact/Law": "exponential",
                                      "Contact/Potential stiffness": "100"}),
    "impact_alpha": ("impact", {"Time stepping/Scheme": "generalized alpha",
                                "Time stepping/Spectral radius": "0.8"}),
    "ref_dashpot": ("reference", {"Reference models/Model": "dashpot",
                                  "Reference models/Damping ratios": "0.1, 1"}),
    "ref_spheres": ("reference", {"Reference models/Model": "spheres",
                                  "Reference models/Velocity ratios": "1e-4, 1"}),
    "ref_rayleigh": ("reference", {"Reference models/Model": "rayleigh",
                                   "Reference models/Velocities": "0.001",
                                   "Reference models/Mode counts": "10, 25"}),
}


def base(key, changes=None):
    """A fresh Prm of base or variant KEY with CHANGES ({path: value})."""
    if key in VARIANTS:
        parent, settings = VARIANTS[key]
        prm = base(parent, settings)
    else:
        top_entries, sections = BASES[key]
        prm = Prm(top_entries, copy.deepcopy(sections))
    for path, value in (changes or {}).items():
        prm.set(path, value)
    return prm


# --------------------------------------------------------------------------
# Cases
# --------------------------------------------------------------------------


class Case:
    """One bad input: the parameter file's content (None: no such file), its
    auxiliary files {name: str or bytes} and empty directories."""

    def __init__(self, name, what, expect, text, prm="case.prm", files=None,
                 dirs=(), ranks=1):
        self.name, self.what, self.expect = name, what, expect
        self.text, self.prm, self.ranks = text, prm, ranks
        self.files, self.dirs = dict(files or {}), list(dirs)

    def record(self):
        return {"name": self.name, "directory": self.name, "prm": self.prm,
                "ranks": self.ranks, "expect": self.expect, "what": self.what}


def comment(what, expect):
    return (f"Robustness case (generated by tests/robustness/generate_cases.py)."
            f"\nWhat is wrong: {what}\n"
            f"Expected: exit code 1, one line 'diskimpact: error: ...' "
            f"naming '{expect}', nothing written.")


def prm_case(name, what, expect, prm, **kwargs):
    """A case whose parameter file is PRM rendered with the comment."""
    return Case(name, what, expect, prm.render(comment(what, expect)), **kwargs)


def slug(text):
    return "".join(c if c.isalnum() else "_" for c in text.lower()).strip("_")


# ---- .prm syntax ----------------------------------------------------------


def edited(what, expect, edit, key="modal"):
    """The base's text with EDIT (a function of the lines) applied."""
    lines = base(key).render(comment(what, expect)).splitlines()
    return "\n".join(edit(lines)) + "\n"


def replace_line(old, new):
    """An edit replacing the first line equal (stripped) to OLD by NEW
    (a list of lines)."""
    def edit(lines):
        i = [line.strip() for line in lines].index(old)
        return lines[:i] + new + lines[i + 1:]
    return edit


def without_last_end(lines):
    """An edit dropping the file's last 'end'."""
    i = len(lines) - 1 - lines[::-1].index("end")
    return lines[:i] + lines[i + 1:]


def syntax_cases():
    specs = [
        ("missing_end", "the last subsection is not closed by 'end'", "end",
         without_last_end),
        ("end_without_subsection", "an 'end' at the top level, no subsection open",
         "subsection", replace_line("set Task = modal analysis",
                                    ["set Task = modal analysis", "end"])),
        ("extra_end", "one 'end' too many at the end of the file", "subsection",
         lambda lines: lines + ["end"]),
        ("misspelled_end", "'ned' instead of 'end'", "ned",
         lambda lines: without_last_end(lines) + ["ned"]),
        ("garbage_line", "a line that is not a statement", "this line is garbage",
         replace_line("subsection Geometry",
                      ["subsection Geometry", "  this line is garbage"])),
        ("set_missing", "an entry without 'set'", "Radius = 1",
         replace_line("set Radius = 1", ["  Radius = 1"])),
        ("missing_equals", "'set' without '='", "Task",
         replace_line("set Task = modal analysis", ["set Task modal analysis"])),
        ("unknown_subsection", "misspelled subsection 'Geometri'", "Geometri",
         replace_line("subsection Geometry", ["subsection Geometri"])),
        ("nested_unknown_subsection", "a subsection 'Mesh' inside Geometry", "Mesh",
         replace_line("subsection Geometry",
                      ["subsection Geometry", "  subsection Mesh", "  end"])),
        ("subsection_without_name", "'subsection' without a name", "subsection",
         replace_line("subsection Geometry", ["subsection", "end",
                                              "subsection Geometry"])),
        ("misspelled_entry", "'Poisson ration' instead of 'Poisson ratio'",
         "Poisson ration",
         replace_line("set Poisson ratio = 0.3", ["  set Poisson ration = 0.3"])),
        ("entry_wrong_case", "'poisson ratio' (entries are case-sensitive)",
         "poisson ratio",
         replace_line("set Poisson ratio = 0.3", ["  set poisson ratio = 0.3"])),
        ("entry_outside_subsection", "'Radius' at the top level", "Radius",
         replace_line("set Task = modal analysis",
                      ["set Task = modal analysis", "set Radius = 1"])),
        ("entry_in_wrong_subsection", "'Radius' in subsection Material", "Radius",
         replace_line("subsection Material",
                      ["subsection Material", "  set Radius = 1"])),
        ("set_set", "'set set' (duplicated keyword)", "set Task",
         replace_line("set Task = modal analysis", ["set set Task = modal analysis"])),
        ("sett", "'sett' instead of 'set'", "sett",
         replace_line("set Task = modal analysis", ["sett Task = modal analysis"])),
    ]
    cases = [Case("syntax_" + name, what, expect, edited(what, expect, edit))
             for name, what, expect, edit in specs]
    return cases + file_cases() + include_cases()


def file_cases():
    junk = bytes(random.Random(20240501).randrange(256) for _ in range(2048))
    return [
        Case("syntax_empty_file", "the parameter file is empty (0 bytes)",
             "empty", ""),
        Case("syntax_binary_junk", "the parameter file is 2 kB of random bytes",
             "junk.prm", junk, prm="junk.prm"),
        Case("syntax_missing_file", "the parameter file does not exist",
             "no_such_file.prm", None, prm="no_such_file.prm"),
        Case("syntax_directory", "the parameter file is a directory",
             "directory", None, prm="folder.prm", dirs=["folder.prm"]),
    ]


def include_cases():
    def including(what, expect, target):
        return edited(what, expect, replace_line(
            "set Task = modal analysis",
            ["include " + target, "set Task = modal analysis"]))

    def mutual(other, what):
        return f"# {what}\ninclude {other}\nset Output directory = {OUTPUT_DIRECTORY}\n"

    what = "includes a file that does not exist"
    self_what = "the file includes itself"
    mutual_what = "a.prm includes b.prm, which includes a.prm"
    dir_what = "includes a directory"
    return [
        Case("syntax_include_missing", what, "not_there.prm",
             including(what, "not_there.prm", "not_there.prm")),
        Case("syntax_include_self", self_what, "include",
             including(self_what, "include", "case.prm")),
        Case("syntax_include_mutual", mutual_what, "include",
             mutual("b.prm", mutual_what), prm="a.prm",
             files={"b.prm": mutual("a.prm", mutual_what)}),
        Case("syntax_include_directory", dir_what, "included_dir",
             including(dir_what, "included_dir", "included_dir"),
             dirs=["included_dir"]),
    ]


# ---- selections -------------------------------------------------------------

SELECTIONS = [
    ("Task", "modal analyses", "modal"),
    ("Task", "Impact", "modal"),
    ("Task", "", "modal"),
    ("Geometry/Domain", "quarter disk", "modal"),
    ("Geometry/Body", "ellipse", "modal"),
    ("Geometry/Body", "", "modal"),
    ("Material/Plane model", "plane", "modal"),
    ("Contact/Law", "hertz", "impact"),
    ("Time stepping/Scheme", "euler", "impact"),
    ("Time stepping/Contact mass", "lumped", "impact"),
    ("Impact/Convergence study per point", "maybe", "sweep"),
    ("Reference models/Model", "sphere", "reference"),
    ("Modal expansion/Integrator", "rk4", "expansion"),
]


def selection_cases():
    cases = []
    for path, value, key in SELECTIONS:
        entry = split_path(path)[1]
        what = f"'{entry} = {value}' is not one of the choices"
        name = f"select_{slug(entry)}_{slug(value) or 'empty'}"
        cases.append(prm_case(name, what, entry, base(key).set(path, value)))
    return cases


# ---- malformed numbers --------------------------------------------------------

# Every numeric entry: (path, kind, base, a valid element for list cases).
NUMERIC_ENTRIES = [
    ("Geometry/Radius", "double", "modal", None),
    ("Geometry/Global refinements", "int", "modal", None),
    ("Geometry/Contact refinements", "int", "modal", None),
    ("Material/Young modulus", "double", "modal", None),
    ("Material/Poisson ratio", "double", "modal", None),
    ("Material/Density", "double", "modal", None),
    ("Material/Relaxation time", "double", "impact", None),
    ("Material/Shear viscosity", "double", "impact", None),
    ("Material/Bulk viscosity", "double", "impact", None),
    ("Finite element/Degree", "int", "modal", None),
    ("Modal analysis/Number of modes", "int", "modal", None),
    ("Modal analysis/Eigensolver tolerance", "double", "modal", None),
    ("Modal convergence/Degrees", "list", "modalconv", "1"),
    ("Modal convergence/Refinement levels", "list", "modalconv", "1"),
    ("Modal convergence/Modes compared", "int", "modalconv", None),
    ("Contact/Penalty factor", "double", "quasistatic", None),
    ("Contact/Potential stiffness", "double", "impact_exponential", None),
    ("Contact/Wall point", "list", "quasistatic", "0"),
    ("Contact/Wall normal", "list", "quasistatic", "1"),
    ("Quasistatic contact/Loads", "list", "quasistatic", "1e-3"),
    ("Quasistatic contact/Elements across contact", "int", "quasistatic", None),
    ("Quasistatic contact/Grading", "double", "quasistatic", None),
    ("Quasistatic contact/Newton tolerance", "double", "quasistatic", None),
    ("Quasistatic contact/Maximum Newton iterations", "int", "quasistatic", None),
    ("Time stepping/Spectral radius", "double", "impact_alpha", None),
    ("Time stepping/Time step", "double", "impact", None),
    ("Time stepping/Time step fraction", "double", "impact", None),
    ("Time stepping/Newton tolerance", "double", "impact", None),
    ("Time stepping/Maximum Newton iterations", "int", "impact", None),
    ("Time stepping/Maximum step cuts", "int", "impact", None),
    ("Impact/Velocity", "double", "impact", None),
    ("Impact/Elements across contact", "int", "impact", None),
    ("Impact/Grading", "double", "impact", None),
    ("Impact/Graded half-width", "double", "impact", None),
    ("Impact/Layer refinement", "int", "impact", None),
    ("Impact/One-DOF law constant", "double", "impact", None),
    ("Impact/Output interval", "int", "impact", None),
    ("Impact/Number of projected modes", "int", "impact", None),
    ("Impact/Margin", "double", "impact", None),
    ("Impact/Velocities", "list", "sweep", "0.05"),
    ("Impact/Poisson ratios", "list", "sweep", "0.33"),
    ("Impact/Relaxation times", "list", "sweep", "0.05"),
    ("Impact convergence/Mesh levels", "int", "impactconv", None),
    ("Impact convergence/Time step levels", "int", "impactconv", None),
    ("Impact convergence/Penalty levels", "int", "impactconv", None),
    ("Impact convergence/Degree levels from", "int", "impactconv", None),
    ("Reference models/Velocities", "list", "reference", "0.01"),
    ("Reference models/Relaxation times", "list", "reference", "0.05"),
    ("Reference models/Damping ratios", "list", "ref_dashpot", "0.1"),
    ("Reference models/Velocity ratios", "list", "ref_spheres", "1e-4"),
    ("Reference models/Mode counts", "list", "ref_rayleigh", "10"),
    ("Modal expansion/Velocities", "list", "expansion", "0.1"),
    ("Modal expansion/Potential stiffnesses", "list", "expansion", "100"),
    ("Modal expansion/Mode counts", "list", "expansion", "20"),
    ("Modal expansion/In-plane Poisson ratios", "list", "expansion", "0.33"),
    ("Modal expansion/Angular points", "int", "expansion", None),
    ("Modal expansion/Steps per period", "double", "expansion", None),
    ("Modal expansion/Number of listed modes", "int", "expansion", None),
]

# Malformed values per kind: (value, name, description).
MALFORMED = {
    "double": [("abc", "text", "text"), ("1x", "1x", "a number with trailing text"),
               ("nan", "nan", "nan"), ("inf", "inf", "inf"),
               ("-inf", "minus_inf", "-inf"), ("", "empty", "empty")],
    "int": [("abc", "text", "text"), ("1x", "1x", "a number with trailing text"),
            ("1.5", "fraction", "not an integer"), ("", "empty", "empty")],
    "list": [("{x}, abc", "text", "text in the list"),
             ("{x}, nan", "nan", "nan in the list"),
             ("{x}, inf", "inf", "inf in the list"),
             ("{x},", "trailing_comma", "a trailing comma"),
             ("{x}, , {x}", "empty_element", "an empty element")],
}


def section_slug(section):
    return {"Finite element": "fe", "Modal analysis": "modal",
            "Modal convergence": "modalconv", "Quasistatic contact": "quasistatic",
            "Time stepping": "time", "Impact convergence": "impactconv",
            "Reference models": "reference", "Modal expansion": "expansion",
            }.get(section, slug(section))


def entry_name(path):
    section, entry = split_path(path)
    return f"{section_slug(section)}_{slug(entry)}"


def malformed_cases():
    cases = []
    for path, kind, key, element in NUMERIC_ENTRIES:
        entry = split_path(path)[1]
        for template, suffix, description in MALFORMED[kind]:
            value = template.format(x=element)
            what = f"'{entry}' is {description}: '{value}'"
            cases.append(prm_case(f"value_{entry_name(path)}_{suffix}", what,
                                  entry, base(key).set(path, value)))
    return cases


# ---- values out of range -----------------------------------------------------

# (path, value, base, what is wrong, extra settings); expected: the entry.
OUT_OF_RANGE = [
    ("Geometry/Radius", "0", "modal", "zero radius", {}),
    ("Geometry/Radius", "-1", "modal", "negative radius", {}),
    ("Geometry/Radius", "1e-308", "modal", "tiny radius (1e-308)", {}),
    ("Geometry/Radius", "1e308", "modal", "huge radius (1e308)", {}),
    ("Geometry/Radius", "1e-308", "impact", "tiny radius (1e-308)", {}),
    ("Geometry/Global refinements", "-1", "modal", "negative", {}),
    ("Geometry/Global refinements", "13", "modal", "above the range 0 ... 12", {}),
    ("Geometry/Global refinements", "12", "modal",
     "2e8 cells of the built-in full disk: far more memory than available", {}),
    ("Geometry/Global refinements", "12", "impact",
     "1e8 cells of the built-in half disk: far more memory than available", {}),
    ("Geometry/Global refinements", "10", "modal",
     "12.6 million Q4 cells: far more memory than available",
     {"Finite element/Degree": "4"}),
    ("Geometry/Contact refinements", "-1", "modal", "negative", {}),
    ("Geometry/Contact refinements", "21", "modal", "above the range 0 ... 20", {}),
    ("Material/Young modulus", "0", "modal", "zero", {}),
    ("Material/Young modulus", "-1", "modal", "negative", {}),
    ("Material/Poisson ratio", "0.5", "modal", "0.5 in plane strain (needs < 0.5)", {}),
    ("Material/Poisson ratio", "0.7", "modal", "0.7 in plane strain", {}),
    ("Material/Poisson ratio", "-1", "modal", "-1 (needs > -1)", {}),
    ("Material/Poisson ratio", "-1.5", "modal", "-1.5 (needs > -1)", {}),
    ("Material/Poisson ratio", "0.51", "modal", "0.51 in plane stress (needs <= 0.5)",
     {"Material/Plane model": "plane stress"}),
    ("Material/Poisson ratio", "-1", "modal", "-1 in plane stress (needs > -1)",
     {"Material/Plane model": "plane stress"}),
    ("Material/Density", "0", "modal", "zero", {}),
    ("Material/Density", "-1", "modal", "negative", {}),
    ("Material/Relaxation time", "-0.1", "impact", "negative", {}),
    ("Material/Shear viscosity", "-1", "impact", "negative", {}),
    ("Material/Bulk viscosity", "-1", "impact", "negative", {}),
    ("Finite element/Degree", "0", "modal", "below the range 1 ... 6", {}),
    ("Finite element/Degree", "7", "modal", "above the range 1 ... 6", {}),
    ("Modal analysis/Number of modes", "0", "modal", "zero", {}),
    ("Modal analysis/Number of modes", "-1", "modal", "negative", {}),
    ("Modal analysis/Number of modes", "2001", "modal", "above 2000", {}),
    ("Modal analysis/Eigensolver tolerance", "0", "modal", "zero", {}),
    ("Modal analysis/Eigensolver tolerance", "-1e-10", "modal", "negative", {}),
    ("Modal analysis/Eigensolver tolerance", "1e-3", "modal", "above 1e-4", {}),
    ("Modal convergence/Degrees", "0, 1", "modalconv", "degree 0", {}),
    ("Modal convergence/Degrees", "1, 5", "modalconv", "degree 5", {}),
    ("Modal convergence/Degrees", "", "modalconv", "empty list", {}),
    ("Modal convergence/Refinement levels", "1", "modalconv",
     "one level: no observed order", {}),
    ("Modal convergence/Refinement levels", "-1, 1", "modalconv", "negative level", {}),
    ("Modal convergence/Refinement levels", "1, 11", "modalconv", "level 11 > 10", {}),
    ("Modal convergence/Refinement levels", "3, 2", "modalconv",
     "levels not ascending", {}),
    ("Modal convergence/Refinement levels", "2, 2", "modalconv",
     "a level repeated (h ratio 1: no observed order)", {}),
    ("Modal convergence/Refinement levels", "1, 10", "modalconv",
     "level 10 of a Q4 disk: far more memory than available",
     {"Modal convergence/Degrees": "4"}),
    ("Modal convergence/Modes compared", "0", "modalconv", "zero", {}),
    ("Modal convergence/Modes compared", "201", "modalconv", "above 200", {}),
    ("Contact/Penalty factor", "0", "quasistatic", "zero", {}),
    ("Contact/Penalty factor", "-100", "quasistatic", "negative", {}),
    ("Contact/Penalty factor", "0", "impact", "zero", {}),
    ("Contact/Penalty factor", "-100", "impact", "negative", {}),
    ("Contact/Potential stiffness", "0", "impact_exponential", "zero", {}),
    ("Contact/Potential stiffness", "-100", "impact_exponential", "negative", {}),
    ("Contact/Wall point", "0", "quasistatic", "one coordinate", {}),
    ("Contact/Wall point", "0, 0, 0", "quasistatic", "three coordinates", {}),
    ("Contact/Wall point", "", "quasistatic", "empty", {}),
    ("Contact/Wall normal", "0, 0", "quasistatic", "zero vector", {}),
    ("Contact/Wall normal", "1", "quasistatic", "one component", {}),
    ("Contact/Wall normal", "", "quasistatic", "empty", {}),
    ("Contact/Wall normal", "0, 0", "impact", "zero vector", {}),
    ("Quasistatic contact/Loads", "", "quasistatic", "empty list", {}),
    ("Quasistatic contact/Loads", "0", "quasistatic", "zero load", {}),
    ("Quasistatic contact/Loads", "-1e-4", "quasistatic", "negative load", {}),
    ("Quasistatic contact/Loads", "1e-4, 0.06", "quasistatic",
     "second load above 0.05", {}),
    ("Quasistatic contact/Elements across contact", "3", "quasistatic",
     "below 4", {}),
    ("Quasistatic contact/Elements across contact", "1001", "quasistatic",
     "above 1000", {}),
    ("Quasistatic contact/Grading", "0", "quasistatic", "zero", {}),
    ("Quasistatic contact/Grading", "1.5", "quasistatic", "above 1", {}),
    ("Quasistatic contact/Newton tolerance", "0", "quasistatic", "zero", {}),
    ("Quasistatic contact/Newton tolerance", "1e-2", "quasistatic", "above 1e-3", {}),
    ("Quasistatic contact/Maximum Newton iterations", "0", "quasistatic", "zero", {}),
    ("Quasistatic contact/Maximum Newton iterations", "-1", "quasistatic",
     "negative", {}),
    ("Time stepping/Spectral radius", "-0.1", "impact_alpha", "below 0", {}),
    ("Time stepping/Spectral radius", "1.1", "impact_alpha", "above 1", {}),
    ("Time stepping/Time step", "-1", "impact", "negative", {}),
    ("Time stepping/Time step", "1e-300", "impact",
     "1e-300: about 1e300 steps, the run would never end", {}),
    ("Time stepping/Time step fraction", "0", "impact", "zero", {}),
    ("Time stepping/Time step fraction", "-0.01", "impact", "negative", {}),
    ("Time stepping/Time step fraction", "0.6", "impact", "above 0.5", {}),
    ("Time stepping/Newton tolerance", "0", "impact", "zero", {}),
    ("Time stepping/Newton tolerance", "1e-2", "impact", "above 1e-3", {}),
    ("Time stepping/Maximum Newton iterations", "0", "impact", "zero", {}),
    ("Time stepping/Maximum step cuts", "-1", "impact", "negative", {}),
    ("Time stepping/Maximum step cuts", "21", "impact", "above 20", {}),
    ("Impact/Velocity", "0", "impact", "zero (needs 0 < v <= 0.5)", {}),
    ("Impact/Velocity", "-0.1", "impact", "negative (needs 0 < v <= 0.5)", {}),
    ("Impact/Velocity", "0.6", "impact", "above 0.5", {}),
    ("Impact/Velocity", "0.6", "impactconv", "above 0.5", {}),
    ("Impact/Elements across contact", "3", "impact", "below 4", {}),
    ("Impact/Elements across contact", "1001", "impact", "above 1000", {}),
    ("Impact/Grading", "0", "impact", "zero", {}),
    ("Impact/Grading", "2", "impact", "above 1", {}),
    ("Impact/Layer refinement", "-3", "impact", "below -2", {}),
    ("Impact/Layer refinement", "3", "impact", "above 2", {}),
    ("Impact/Graded half-width", "-0.1", "impact", "negative", {}),
    ("Impact/Graded half-width", "1.5", "impact", "above 1 (the radius)", {}),
    ("Impact/One-DOF law constant", "fitted", "impact",
     "neither 'fit' nor a number", {}),
    ("Impact/Output interval", "-1", "impact", "negative", {}),
    ("Impact/Number of projected modes", "-1", "impact", "negative", {}),
    ("Impact/Number of projected modes", "401", "impact", "above 400", {}),
    ("Impact/Margin", "-0.1", "impact", "negative", {}),
    ("Impact/Margin", "11", "impact", "above 10", {}),
    ("Impact/Velocities", "", "sweep", "empty list: nothing to sweep", {}),
    ("Impact/Velocities", "0.1, 0.6", "sweep", "second velocity above 0.5", {}),
    ("Impact/Velocities", "0, 0.1", "sweep", "first velocity zero", {}),
    ("Impact/Velocities", "-0.1", "sweep", "negative velocity", {}),
    ("Impact/Poisson ratios", "0.3, 0.5", "sweep",
     "second ratio 0.5 in plane strain (needs < 0.5)",
     {"Material/Plane model": "plane strain", "Material/Poisson ratio": "0.3"}),
    ("Impact/Poisson ratios", "0.3, 0.6", "sweep",
     "second ratio 0.6 in plane stress (needs <= 0.5)", {}),
    ("Impact/Poisson ratios", "0.3, -1", "sweep", "second ratio -1", {}),
    ("Impact/Relaxation times", "-0.1", "sweep", "negative", {}),
    ("Impact/Relaxation times", "0, -0.05", "sweep", "second entry negative", {}),
    ("Impact convergence/Mesh levels", "0", "impactconv", "zero", {}),
    ("Impact convergence/Mesh levels", "7", "impactconv", "above 6", {}),
    ("Impact convergence/Time step levels", "0", "impactconv", "zero", {}),
    ("Impact convergence/Time step levels", "9", "impactconv", "above 8", {}),
    ("Impact convergence/Penalty levels", "0", "impactconv", "zero", {}),
    ("Impact convergence/Penalty levels", "7", "impactconv", "above 6", {}),
    ("Impact convergence/Degree levels from", "7", "impactconv", "above 6", {}),
    ("Reference models/Velocities", "0", "reference", "zero velocity", {}),
    ("Reference models/Velocities", "-0.1", "reference", "negative velocity", {}),
    ("Reference models/Velocities", "0.001, 0.3", "ref_rayleigh",
     "0.3 is too fast for the log law", {}),
    ("Reference models/Relaxation times", "-0.1", "reference", "negative", {}),
    ("Reference models/Damping ratios", "-0.1", "ref_dashpot", "negative", {}),
    ("Reference models/Velocity ratios", "0", "ref_spheres", "zero", {}),
    ("Reference models/Velocity ratios", "-1", "ref_spheres", "negative", {}),
    ("Reference models/Mode counts", "0", "ref_rayleigh", "zero", {}),
    ("Reference models/Mode counts", "-5", "ref_rayleigh", "negative", {}),
    ("Modal expansion/Velocities", "0", "expansion", "zero", {}),
    ("Modal expansion/Velocities", "-0.1", "expansion", "negative", {}),
    ("Modal expansion/Velocities", "0.1, 1.5", "expansion", "1.5 >= 1", {}),
    ("Modal expansion/Potential stiffnesses", "0", "expansion", "zero", {}),
    ("Modal expansion/Potential stiffnesses", "-100", "expansion", "negative", {}),
    ("Modal expansion/Mode counts", "0", "expansion", "zero", {}),
    ("Modal expansion/In-plane Poisson ratios", "1", "expansion",
     "in-plane ratio 1 (needs -1 < nu2 < 1)", {}),
    ("Modal expansion/In-plane Poisson ratios", "1.5", "expansion", "in-plane ratio 1.5", {}),
    ("Modal expansion/In-plane Poisson ratios", "-1", "expansion", "in-plane ratio -1", {}),
    ("Modal expansion/Angular points", "1", "expansion", "below 2", {}),
    ("Modal expansion/Angular points", "0", "expansion", "zero", {}),
    ("Modal expansion/Steps per period", "1", "expansion", "below 2", {}),
    ("Modal expansion/Steps per period", "0", "expansion", "zero", {}),
    ("Modal expansion/Number of listed modes", "-1", "expansion", "negative", {}),
    ("Modal expansion/Number of listed modes", "101", "expansion", "above 100", {}),
]


# Where the entry's name is also the start of another entry's name, the
# quoted name (the messages' style), so that a message blaming the other
# entry does not pass.
RANGE_EXPECT = {("Time stepping/Time step", "1e-300"): "'Time step'"}


def value_slug(value):
    """'0.1, 0.6' -> '0p1_0p6', '-1e-4' -> 'm1em4', '' -> 'empty'."""
    special = {"": "empty", "0": "zero"}
    return special.get(value) or slug(
        value.replace(", ", "_").replace(".", "p").replace("-", "m"))


def range_cases():
    cases, names = [], set()
    for path, value, key, what, extra in OUT_OF_RANGE:
        entry = split_path(path)[1]
        name = f"range_{entry_name(path)}_{value_slug(value)}"
        if name in names:
            name += "_" + (slug("_".join(extra.values())) or key)
        names.add(name)
        prm = base(key, extra).set(path, value)
        description = f"'{entry} = {value}' ({key}): {what}"
        expect = RANGE_EXPECT.get((path, value), entry)
        cases.append(prm_case(name, description, expect, prm))
    return cases


# ---- combinations ---------------------------------------------------------------

# (name, base, settings, expected, what is wrong).
COMBINATIONS = [
    ("layers_2d", "impact", {"Impact/Layer refinement": "1"},
     "Layer refinement", "'Layer refinement' of a disk in 2D (only a 3D disk has layers)"),
    ("quasistatic_full_disk", "quasistatic", {"Geometry/Domain": "full disk"},
     "Domain", "task 'quasistatic contact' with 'Domain = full disk'"),
    ("quasistatic_exponential", "quasistatic", {"Contact/Law": "exponential"},
     "Law", "task 'quasistatic contact' with 'Law = exponential'"),
    ("quasistatic_wall_misses", "quasistatic", {"Contact/Wall point": "-0.1, 0"},
     "wall", "the wall x = -0.1 misses the disk (gap 0.1 R)"),
    ("quasistatic_wall_cuts_disk", "quasistatic", {"Contact/Wall point": "0.2, 0"},
     "wall", "the wall x = 0.2 cuts into the undeformed disk"),
    ("quasistatic_wall_behind", "quasistatic", {"Contact/Wall normal": "-1, 0"},
     "Wall normal", "the wall normal points away from the disk"),
    ("quasistatic_wall_oblique", "quasistatic",
     {"Contact/Wall normal": "1, 1",
      "Contact/Wall point": "0.29289321881345254, -0.70710678118654752"},
     "Wall normal", "an oblique wall (touching the disk) with a half disk, "
     "which is symmetric about y = 0"),
    ("impact_wall_misses", "impact", {"Contact/Wall point": "-0.5, 0"},
     "wall", "the wall x = -0.5 is 0.5 R from the disk (at most 0.05 R)"),
    ("impact_wall_cuts_disk", "impact", {"Contact/Wall point": "0.2, 0"},
     "wall", "the wall x = 0.2 cuts into the undeformed disk"),
    ("impact_wall_behind", "impact", {"Contact/Wall normal": "-1, 0"},
     "Wall normal", "the wall normal points away from the disk"),
    ("impact_wall_along_axis", "impact",
     {"Contact/Wall normal": "0, 1", "Contact/Wall point": "0, -1"},
     "Wall normal", "a wall below the half disk, parallel to the impact axis"),
    ("sweep_wall_misses", "sweep", {"Contact/Wall point": "-1, 0"},
     "wall", "the wall x = -1 is R from the disk"),
    ("modal_more_modes_than_dofs", "modal",
     {"Geometry/Global refinements": "0", "Finite element/Degree": "1",
      "Modal analysis/Number of modes": "100"},
     "Number of modes", "100 modes of a mesh with fewer than 100 DoFs"),
    ("modalconv_more_modes_than_dofs", "modalconv",
     {"Modal convergence/Degrees": "1", "Modal convergence/Refinement levels": "0, 1",
      "Modal convergence/Modes compared": "200"},
     "Modes compared", "200 distinct modes of meshes with fewer DoFs"),
    ("sphere_domain", "modal", {"Geometry/Body": "sphere"}, "Domain",
     "a sphere with 'Domain = full disk' (a disk entry)"),
    ("sphere_plane_model", "modal",
     {"Geometry/Body": "sphere", "Geometry/Domain": ""}, "Plane model",
     "a sphere with 'Plane model = plane strain' (a disk entry)"),
    ("sphere_shear_viscosity", "modal",
     {"Geometry/Body": "sphere", "Geometry/Domain": "",
      "Material/Plane model": "", "Material/Shear viscosity": "0.1"},
     "Shear viscosity", "a sphere with an in-plane viscosity of a disk"),
    ("sphere_reference_models", "reference",
     {"Geometry/Body": "sphere", "Geometry/Domain": "",
      "Material/Plane model": ""},
     "sphere", "the disk's reduced models with a sphere"),
    ("disk_revolved_view", "impact", {"Impact/Revolved view": "90"},
     "Revolved view", "a disk with the sphere's 3D view"),
    ("disk_finite_size_law", "impact",
     {"Impact/One-DOF law constant": "finite size"}, "finite size",
     "a disk with the sphere's derived finite-size wall law"),
    ("output_directory_is_a_file", "modal", {}, "Output directory",
     "'output' exists as a regular file, so output/case cannot be created"),
    ("output_directory_below_file", "modal",
     {"Output directory": "existing_file/case"}, "Output directory",
     "the output directory lies below a regular file"),
]

COMBINATION_FILES = {
    "output_directory_is_a_file": {"output": "not a directory\n"},
    "output_directory_below_file": {"existing_file": "not a directory\n"},
}


def combination_cases():
    return [prm_case("combo_" + name, what, expect, base(key, settings),
                     files=COMBINATION_FILES.get(name))
            for name, key, settings, expect, what in COMBINATIONS]


# --------------------------------------------------------------------------
# Meshes
# --------------------------------------------------------------------------

# A disk of radius R centred at (R, 0) like meshes/disk.geo, with options:
# a hole of radius r, triangles (recombine = 0), a 3D slab (extrude = 1).
PLAIN_DISK_GEO = """\
DefineConstant[ R = 1, r = 0, recombine = 1, extrude = 0, h = 0.4 ];
Point(1) = {R, 0, 0, h};
Point(2) = {0, 0, 0, h};
Point(3) = {R, R, 0, h};
Point(4) = {2 * R, 0, 0, h};
Point(5) = {R, -R, 0, h};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {-4, -3, -2, -1};
If (r > 0)
  Point(6) = {R - r, 0, 0, h};
  Point(7) = {R, r, 0, h};
  Point(8) = {R + r, 0, 0, h};
  Point(9) = {R, -r, 0, h};
  Circle(5) = {6, 1, 7};
  Circle(6) = {7, 1, 8};
  Circle(7) = {8, 1, 9};
  Circle(8) = {9, 1, 6};
  Curve Loop(2) = {5, 6, 7, 8};
  Plane Surface(1) = {1, 2};
  Physical Curve("hole", 3) = {5, 6, 7, 8};
Else
  Plane Surface(1) = {1};
EndIf
Physical Curve("curved boundary", 1) = {1, 2, 3, 4};
If (recombine)
  Mesh.RecombineAll = 1;
  Mesh.SubdivisionAlgorithm = 1;
EndIf
If (extrude)
  out[] = Extrude {0, 0, 0.5 * R} { Surface{1}; Layers{1}; Recombine; };
  Physical Volume("slab", 1) = {out[1]};
Else
  Physical Surface("disk", 1) = {1};
EndIf
Mesh.MshFileVersion = 2.2;
"""


def run_gmsh(gmsh, args, output):
    """Run gmsh with ARGS writing OUTPUT; its text is returned."""
    result = subprocess.run([gmsh] + args + ["-o", str(output)],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if result.returncode != 0 or not output.exists():
        sys.exit(f"generate_cases.py: gmsh {' '.join(args)} failed:\n"
                 + result.stdout.decode(errors="replace")[-2000:])
    return output.read_text(errors="surrogateescape")


def gmsh_meshes(gmsh, work):
    """The meshes made by gmsh: {name: text}."""
    plain = work / "plain.geo"
    plain.write_text(PLAIN_DISK_GEO)
    coarse = ["-setnumber", "h_far", "0.5", "-setnumber", "h_contact", "0.2"]
    disk = ["-2", str(DISK_GEO), "-format", "msh2"]
    meshes = {
        "full": run_gmsh(gmsh, disk + coarse, work / "full.msh"),
        "half": run_gmsh(gmsh, disk + coarse + ["-setnumber", "half", "1"],
                         work / "half.msh"),
        "radius2": run_gmsh(gmsh, disk + ["-setnumber", "R", "2", "-setnumber",
                                          "h_far", "1", "-setnumber", "h_contact",
                                          "0.4"], work / "radius2.msh"),
        "triangles": run_gmsh(gmsh, ["-2", str(plain), "-setnumber", "recombine",
                                     "0"], work / "triangles.msh"),
        "hole": run_gmsh(gmsh, ["-2", str(plain), "-setnumber", "r", "0.4"],
                         work / "hole.msh"),
        "slab": run_gmsh(gmsh, ["-3", str(plain), "-setnumber", "extrude", "1"],
                         work / "slab.msh"),
    }
    run_gmsh(gmsh, [str(work / "full.msh"), "-save", "-format", "msh2", "-bin"],
             work / "binary.msh")
    meshes["binary"] = (work / "binary.msh").read_bytes()
    return meshes


def msh_sections(text):
    """The sections of an ASCII msh 2.2 file: [(name, [lines])]."""
    sections, lines = [], text.splitlines()
    i = 0
    while i < len(lines):
        name = lines[i].strip()[1:]
        end = lines.index("$End" + name, i)
        sections.append((name, lines[i + 1:end]))
        i = end + 1
    return sections


def msh_text(sections):
    out = []
    for name, lines in sections:
        out += ["$" + name] + lines + ["$End" + name]
    return "\n".join(out) + "\n"


def edit_msh(text, nodes=None, elements=None):
    """TEXT with its node lines mapped by NODES and its element list
    replaced by ELEMENTS(list of element lines); counts are updated."""
    sections = msh_sections(text)
    for i, (name, lines) in enumerate(sections):
        body = lines[1:]
        if name == "Nodes" and nodes:
            body = [nodes(line) for line in body]
        elif name == "Elements" and elements:
            body = elements(body)
        else:
            continue
        sections[i] = (name, [str(len(body))] + body)
    return msh_text(sections)


def edit_first_quad(lines, change):
    """Element LINES with the first quadrilateral's fields replaced by the
    element lines CHANGE(fields)."""
    out, done = [], False
    for line in lines:
        fields = line.split()
        if fields[1] == "3" and not done:
            out += change(fields)
            done = True
        else:
            out.append(line)
    return out


def two_triangles(fields):
    """Mixed mesh: a quadrilateral a b c d becomes the triangles a b c and
    a c d (same tags)."""
    tags, (a, b, c, d) = fields[2:3 + int(fields[2])], fields[-4:]
    return [" ".join([fields[0], "2"] + tags + [a, b, c]),
            " ".join([str(10 ** 6), "2"] + tags + [a, c, d])]


def dangling_node(fields):
    """The quadrilateral refers to node 99999, which does not exist."""
    return [" ".join(fields[:-1] + ["99999"])]


def shifted(dx, dy):
    def node(line):
        i, x, y, z = line.split()
        return f"{i} {float(x) + dx!r} {float(y) + dy!r} {z}"
    return node


def nan_first_node(text):
    lines = text.splitlines()
    i = lines.index("$Nodes") + 2
    fields = lines[i].split()
    lines[i] = " ".join([fields[0], "nan"] + fields[2:])
    return "\n".join(lines) + "\n"


def square_mesh():
    """A 2 x 2 quadrilateral mesh of the square [0, 2] x [-1, 1]."""
    nodes = [f"{3 * j + i + 1} {i} {j - 1} 0" for j in range(3) for i in range(3)]
    quads = []
    for j in range(2):
        for i in range(2):
            a = 3 * j + i + 1
            quads.append(f"{len(quads) + 1} 3 2 1 1 {a} {a + 1} {a + 4} {a + 3}")
    return msh_text([("MeshFormat", ["2.2 0 8"]),
                     ("Nodes", [str(len(nodes))] + nodes),
                     ("Elements", [str(len(quads))] + quads)])


def mesh_files(gmsh):
    """Every mesh file of the mesh cases: {name: str or bytes}."""
    with tempfile.TemporaryDirectory() as work:
        meshes = gmsh_meshes(gmsh, Path(work))
    full = meshes["full"]
    lines = full.splitlines()
    meshes.update({
        "mixed": edit_msh(full, elements=lambda ls: edit_first_quad(
            ls, two_triangles)),
        "missing_node": edit_msh(full, elements=lambda ls: edit_first_quad(
            ls, dangling_node)),
        "lines_only": edit_msh(full, elements=lambda ls: [
            line for line in ls if line.split()[1] in ("1", "15")]),
        "shifted": edit_msh(full, nodes=shifted(0.5, 0.25)),
        "nan_node": nan_first_node(full),
        "truncated": "\n".join(lines[:len(lines) // 2]) + "\n",
        "empty": "",
        "junk": bytes(random.Random(7).randrange(256) for _ in range(1024)),
        "square": square_mesh(),
    })
    return meshes


# (name, mesh, Domain, expected, what is wrong).
MESH_CASES = [
    ("triangles", "triangles", "full disk", "quadrilateral",
     "a triangle mesh (quadrilaterals needed)"),
    ("mixed", "mixed", "full disk", "quadrilateral",
     "a mesh of quadrilaterals and two triangles"),
    ("lines_only", "lines_only", "full disk", "quadrilateral",
     "only the boundary lines, no cells"),
    ("wrong_radius", "radius2", "full disk", "Radius",
     "a disk of radius 2 with 'Radius = 1'"),
    ("not_centred", "shifted", "full disk", "Radius",
     "a disk centred at (1.5, 0.25) instead of (R, 0)"),
    ("full_mesh_half_domain", "full", "half disk", "Domain",
     "a full-disk mesh with 'Domain = half disk'"),
    ("half_mesh_full_domain", "half", "full disk", "Domain",
     "a half-disk mesh with 'Domain = full disk'"),
    ("square", "square", "full disk", "Radius", "a square, not a disk"),
    ("hole", "hole", "full disk", "boundary", "a disk with a hole"),
    ("3d", "slab", "full disk", "2D", "a 3D mesh of hexahedra"),
    ("binary_msh", "binary", "full disk", "binary.msh", "a binary msh 2.2 file"),
    ("missing_node", "missing_node", "full disk", "missing_node.msh",
     "a cell refers to a node that does not exist"),
    ("nan_node", "nan_node", "full disk", "nan_node.msh", "a node at x = nan"),
    ("truncated", "truncated", "full disk", "truncated.msh",
     "the file ends in the middle"),
    ("empty", "empty", "full disk", "empty.msh", "an empty file"),
    ("junk", "junk", "full disk", "junk.msh", "1 kB of random bytes"),
]


def mesh_prm(mesh_file, domain):
    return base("modal", {"Geometry/Domain": domain, "Geometry/Mesh file": mesh_file,
                          "Geometry/Global refinements": "0",
                          "Finite element/Degree": "1",
                          "Modal analysis/Number of modes": "3"})


def mesh_cases(meshes):
    cases = []
    for name, mesh, domain, expect, what in MESH_CASES:
        file_name = mesh + ".msh"
        cases.append(prm_case("mesh_" + name, f"mesh file {file_name}: {what}",
                              expect, mesh_prm(file_name, domain),
                              files={file_name: meshes[mesh]}))
    cases.append(prm_case("mesh_missing", "the mesh file does not exist", "Mesh file",
                          mesh_prm("no_such_mesh.msh", "full disk")))
    cases.append(prm_case("mesh_directory", "the mesh file is a directory",
                          "directory", mesh_prm("mesh_dir.msh", "full disk"),
                          dirs=["mesh_dir.msh"]))
    cases.append(prm_case("mesh_dev_null", "the mesh file is /dev/null",
                          "/dev/null", mesh_prm("/dev/null", "full disk")))
    cases.append(prm_case("mesh_is_prm", "the mesh file is the parameter file",
                          "case.prm", mesh_prm("case.prm", "full disk")))
    impact = base("impact", {"Geometry/Mesh file": "triangles.msh",
                             "Geometry/Global refinements": "0"})
    cases.append(prm_case("mesh_triangles_impact",
                          "task impact on a triangle mesh", "quadrilateral", impact,
                          files={"triangles.msh": meshes["triangles"]}))
    return cases


# --------------------------------------------------------------------------
# Two MPI ranks
# --------------------------------------------------------------------------

TWO_RANKS = [
    "syntax_missing_end", "syntax_garbage_line", "syntax_include_self",
    "syntax_missing_file", "syntax_empty_file", "value_geometry_radius_nan",
    "range_geometry_global_refinements_12", "range_impact_velocity_0p6",
    "range_impact_velocities_empty", "range_impact_velocities_0p1_0p6",
    "range_impact_poisson_ratios_0p3_0p5", "range_contact_penalty_factor_zero_impact",
    "range_time_time_step_fraction_zero", "range_expansion_velocities_0p1_1p5",
    "range_reference_velocities_0p001_0p3", "combo_quasistatic_full_disk",
    "combo_impact_wall_misses", "combo_modal_more_modes_than_dofs",
    "combo_output_directory_is_a_file", "mesh_triangles", "mesh_missing",
    "mesh_truncated",
]


def two_rank_cases(cases):
    """Copies of the cases named in TWO_RANKS, run on 2 MPI ranks."""
    by_name = {case.name: case for case in cases}
    missing = [name for name in TWO_RANKS if name not in by_name]
    if missing:
        sys.exit(f"generate_cases.py: TWO_RANKS names unknown cases {missing}")
    copies = []
    for name in TWO_RANKS:
        case = copy.deepcopy(by_name[name])
        case.name, case.ranks = name + "_2ranks", 2
        copies.append(case)
    return copies


# --------------------------------------------------------------------------
# Output
# --------------------------------------------------------------------------


def all_cases(gmsh):
    cases = (syntax_cases() + selection_cases() + malformed_cases()
             + range_cases() + combination_cases() + mesh_cases(mesh_files(gmsh)))
    cases += two_rank_cases(cases)
    names = [case.name for case in cases]
    duplicates = {name for name in names if names.count(name) > 1}
    if duplicates:
        sys.exit(f"generate_cases.py: duplicate case names {sorted(duplicates)}")
    return cases


def write_file(path, content):
    if isinstance(content, bytes):
        path.write_bytes(content)
    else:
        path.write_text(content)


def write_case(root, case):
    folder = root / case.name
    folder.mkdir()
    if case.text is not None:
        write_file(folder / case.prm, case.text)
    for name, content in case.files.items():
        write_file(folder / name, content)
    for name in case.dirs:
        (folder / name).mkdir()


def prepare(root):
    """Empty ROOT if it holds a previous suite (manifest.json); refuse to
    touch any other non-empty directory."""
    if root.exists() and any(root.iterdir()):
        if not (root / "manifest.json").exists():
            sys.exit(f"generate_cases.py: {root} is not empty and holds no "
                     "manifest.json; refusing to overwrite it")
        shutil.rmtree(root)
    root.mkdir(parents=True, exist_ok=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output_dir", type=Path)
    parser.add_argument("--gmsh", default="gmsh", help="gmsh executable")
    args = parser.parse_args()
    cases = all_cases(args.gmsh)
    prepare(args.output_dir)
    for case in cases:
        write_case(args.output_dir, case)
    manifest = [case.record() for case in cases]
    (args.output_dir / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
    print(f"{len(cases)} cases ({sum(c.ranks == 2 for c in cases)} on 2 ranks) "
          f"written to {args.output_dir}")


if __name__ == "__main__":
    main()

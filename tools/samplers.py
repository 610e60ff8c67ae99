"""The camera samplers as the charts and tables show them, keyed by the library's registry
names (vrlis::CameraSamplers in include/vrlis/method.hpp, which vrlis_bench, vrlis_accuracy
and vrl_compare print). Shared by bench/plot.py, bench/accuracy_scenes.py and bench/compare/plot.py:
a sampler's label is derived from its name, so the registry stays the one name table.
"""

# vrlis's own samplers; the others are the published methods the README cites.
OWN = {"full-product", "auto"}
# Policies that choose among the other samplers per query: judged by the equal-time study,
# left out of the per-sample speed and accuracy tables.
POLICIES = {"auto"}
_STYLE = {
    "equiangular": ("tab:gray", "o"),
    "novak": ("tab:blue", "s"),
    "cauchy-sum": ("tab:orange", "^"),
    "cauchy-mixture": ("tab:red", "v"),
    "full-product": ("tab:green", "D"),
    "auto": ("tab:brown", "P"),
}


def label(name):
    """The label of a registry name: "full-product" -> "FullProduct"."""
    return "".join(word.capitalize() for word in name.split("-"))


def style(name):
    """(colour, marker) of a sampler in every chart; a sampler new to the registry gets a plain one."""
    return _STYLE.get(name, ("black", "x"))

"""Each pass's Python docstring says what it does and names its main settings.

For every class make_pass() makes: the docstring has its one-line brief, a
"Main settings:" paragraph whose every SetX() is a method of the class, a
Python example that runs (make_pass(...) evaluated), and its C++ example with
its template arguments (VTK's wrapper drops "<T>" as an HTML tag, so the
headers write "vtkNew< T >").
"""
import re
import sys

import vtkshadowmaps


def check(condition, message):
    if not condition:
        print("FAIL:", message)
        sys.exit(1)


def main():
    classes = {pass_class for pass_class, _ in vtkshadowmaps.TECHNIQUES.values()}
    check(len(classes) == 6, "six pass classes behind make_pass, got %d" % len(classes))
    for pass_class in sorted(classes, key=lambda c: c.__name__):
        name = pass_class.__name__
        doc = " ".join(pass_class.__doc__.split())
        check(doc.startswith(name + " - "), name + ": the brief first")
        settings = re.search(r"Main settings: (.*?) In Python: (vtkshadowmaps\.make_pass\(.*?\))\.", doc)
        check(settings is not None, name + ": a 'Main settings:' paragraph and a Python example")
        named = re.findall(r"\b(Set[A-Za-z0-9]+)\(\)", settings.group(1))
        check(len(named) >= 3, name + ": names its main settings")
        for setter in named:
            check(hasattr(pass_class, setter), "%s: %s named but not a method" % (name, setter))
        for example in re.findall(r"make_pass\([^)]*\)", settings.group(2)):
            made = eval("vtkshadowmaps." + example)  # noqa: S307 (the docstring's own example)
            check(isinstance(made, pass_class), "%s: %s makes a %s" % (name, example, name))
        check("vtkNew< " in doc and not re.search(r"vtkNew[A-Za-z]", doc),
              name + ": the C++ example keeps vtkNew's template argument")
    module = " ".join(vtkshadowmaps.__doc__.split())
    for technique in vtkshadowmaps.TECHNIQUES:
        check("``" + technique + "``" in module, "help(vtkshadowmaps) names " + technique)
    print("docstrings: %d pass classes checked" % len(classes))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Writes the malformed-expression scenes tests/scenes/bad/expression_*.yaml (issue 19): each header
pins exit 2, file:line:col of the faulty character (found here from the text, independently of
efg) and the reason. Usage: make_expression_bad_scenes.py (run from the repository root)."""
import os
base = """parameters:
  L: 10
PARAMS
mesh:
  generate: {element: quad4, lower: [0, 0], upper: [L, 2], cells: [CELLS, 4]}
parts:
  - {name: p, blocks: [block_1], material: steel}
materials:
  - {name: steel, model: linear_elastic, youngs_modulus: YOUNG, poissons_ratio: 0.3, density: 7.8e-9}
boundary_conditions:
  - {name: clamp, type: displacement, node_set: xmin, x: 0, y: BCY}
loads:
  - name: tip
    type: traction
    side_set: xmax
    value: [0, "LOAD"]
initial_conditions:
  - {type: velocity, node_set: all, value: [0, "IC"]}
stages:
  - {name: s, driver: explicit, end_time: 1.0e-3}
VERIF"""
# name, what, substitutions, key path, (line marker, offset of the faulty character in the expression) or None, message part
cases = [
 ("missing_paren", "a function call without its closing parenthesis", {"LOAD": "sin(x"}, "loads[0].value[1]", "missing ')'"),
 ("unknown_variable", "a name that is neither a variable nor a parameter", {"LOAD": "2*q"}, "loads[0].value[1]", "unknown name 'q'"),
 ("unknown_function", "a function muParser does not have", {"LOAD": "foo(x)"}, "loads[0].value[1]", "unknown name 'foo'"),
 ("time_in_initial_value", "t in an initial value (position only)", {"IC": "t*x"}, "initial_conditions[0].value[1]", "unknown name 't' (allowed here: the variables x, y, z,"),
 ("too_many_arguments", "sin with two arguments", {"LOAD": "sin(x, y)"}, "loads[0].value[1]", "too many arguments for function 'sin'"),
 ("too_few_arguments", "atan2 with one argument", {"LOAD": "atan2(y)"}, "loads[0].value[1]", "too few arguments for function 'atan2'"),
 ("doubled_operator", "a Fortran power operator", {"LOAD": "2**x"}, "loads[0].value[1]", "Unexpected operator"),
 ("empty", "an empty expression", {"LOAD": ""}, "loads[0].value[1]", "empty expression"),
 ("assignment", "an assignment instead of a comparison", {"LOAD": "x = 2"}, "loads[0].value[1]", "'=' is not allowed"),
 ("two_values", "two values separated by a comma", {"LOAD": "1, 2"}, "loads[0].value[1]", "one value expected, found 2"),
 ("extra_parenthesis", "an unbalanced closing parenthesis", {"LOAD": "(x+1))"}, "loads[0].value[1]", "found '(x+1))'"),
 ("trailing_letter", "a number glued to a name", {"LOAD": "3x"}, "loads[0].value[1]", "found '3x'"),
 ("division_by_zero_at_point", "1/(x - L) on the side x = L", {"LOAD": "1/(x-L)"}, "loads[0].value[1]", "'1/(x-L)' is inf at (10, 0, 0)"),
 ("root_of_negative_at_point", "sqrt(5 - x) on the side x = L", {"LOAD": "sqrt(5-x)"}, "loads[0].value[1]", "'sqrt(5-x)' is nan at (10, 0, 0)"),
 ("log_of_zero_at_point", "ln(x) at the clamp x = 0", {"BCY": "\"ln(x)\""}, "boundary_conditions[0].y", "'ln(x)' is -inf at (0, 0, 0)"),
 ("singular_in_time", "1/(t - 5e-4) in a prescribed value", {"BCY": "\"1/(t-5e-4)\""}, "boundary_conditions[0].y", "t = 0.0005"),
 ("parameter_unknown", "a parameter using one not yet defined", {"PARAMS": "  a: \"2*b\""}, "parameters.a", "unknown name 'b'"),
 ("parameter_reserved", "a parameter named like a variable", {"PARAMS": "  x: 3"}, "parameters.x", "'x' is a variable or function of expressions"),
 ("constant_not_finite", "a modulus of 1/0", {"YOUNG": "\"1/0\""}, "materials[0].youngs_modulus", "found '1/0' = inf (not finite)"),
 ("user_solution_nan", "an exact solution with sqrt(x - 1) at x = 0", {"VERIF": "verification:\n  exact_solution: user\n  user_solution:\n    displacement: [\"sqrt(x-1)\", 0]"}, "verification.user_solution.displacement[0]", "'sqrt(x-1)' is nan at (0, 0, 0)"),
 ("integer_not_whole", "a cell count of L/3", {"CELLS": "\"L/3\""}, "mesh.generate.cells[0]", "expected an integer >= 1"),
 ("number_overflow", "a number beyond the range of double inside an expression, issue 55", {"LOAD": "2*1.5e999"}, "loads[0].value[1]", "the number 1.5e999 is out of the range of double (overflow; magnitudes up to 1.8e308)"),
 ("body_force_singular_in_part", "a body force 1/(x - L), infinite on the part's nodes at x = L", {"LOAD": "1", "IC": "0", "VERIF": "", "PARAMS": ""}, "loads[1].value[0]", "'1/(x-L)' is inf at (10, 0, 0)"),
]
defaults = {"PARAMS": "", "CELLS": "10", "YOUNG": "2e5", "BCY": "0", "LOAD": "1", "IC": "0", "VERIF": ""}
LOCS = {'missing_paren': ('"sin(x"', 6), 'unknown_variable': ('"2*q"', 3), 'unknown_function': ('"foo(x)"', 1), 'time_in_initial_value': ('"t*x"', 1), 'too_many_arguments': ('"sin(x, y)"', 9), 'too_few_arguments': ('"atan2(y)"', 8), 'doubled_operator': ('"2**x"', 3), 'empty': ('[0, ""]', 5), 'assignment': ('"x = 2"', 3), 'two_values': ('"1, 2"', 2), 'extra_parenthesis': ('"(x+1))"', 6), 'trailing_letter': ('"3x"', 2), 'division_by_zero_at_point': ('"1/(x-L)"', 0), 'root_of_negative_at_point': ('"sqrt(5-x)"', 0), 'log_of_zero_at_point': ('"ln(x)"', 0), 'singular_in_time': ('"1/(t-5e-4)"', 0), 'parameter_unknown': ('"2*b"', 3), 'parameter_reserved': ('x: 3', 0), 'constant_not_finite': ('"1/0"', 0), 'user_solution_nan': ('"sqrt(x-1)"', 0), 'integer_not_whole': ('"L/3"', 0), 'number_overflow': ('"2*1.5e999"', 3),
        'body_force_singular_in_part': ('"1/(x-L)"', 0)}
for name, what, subs, path, message in cases:
    text = base
    for k, v in {**defaults, **subs}.items():
        text = text.replace(k, v)
    if name == "body_force_singular_in_part":  # a second load: a body force on the part
        text = text.replace("initial_conditions:", "  - {name: g, type: body_force, parts: [p], "
                            "value: [\"1/(x-L)\", 0]}\ninitial_conditions:")
    text = "\n".join(l for l in text.split("\n") if l.strip() != "")
    fname = f"expression_{name}.yaml"
    marker, offset = LOCS[name]
    body_lines = text.split("\n")
    line = next(i for i, l in enumerate(body_lines) if marker in l)
    column = body_lines[line].index(marker) + 1 + offset
    where = f"tests/scenes/bad/{fname}:{line + 5}:{column}: {path}:"
    header = f"# Malformed on purpose: {what} (issue 19).\n# expect-exit: 2\n# expect-error: {where}\n# expect-error: {message}\n"
    open(os.path.join("tests/scenes/bad", fname), "w").write(header + text + "\n")
print(len(cases))

"""quadmc.integrands(), methods() and point_sets() against what `quadmc list` of the same build
prints (bench/quadmc/catalogue_listing.cpp): each entry laid out in the listing's columns from the
module's dicts gives the listing's line, in the same order, with its key, control and option lines."""
import pytest

import quadmc


@pytest.fixture(scope="module")
def listing(command):
    """`quadmc list` by section: {section's first word: [entry lines, each with its detail lines]}."""
    result = command("list")
    assert result.returncode == 0, result.stderr
    sections, entries = {}, None
    for line in result.stdout.splitlines():
        if not line.strip():
            continue
        if not line.startswith(" "):
            entries = sections.setdefault(line.split(" (")[0], [])
        elif line.startswith("  ") and line[2] != " ":
            entries.append((line[2:], []))
        else:
            entries[-1][1].append(line.strip())
    assert set(sections) >= {"integrands", "methods", "point sets"}, sections.keys()
    return sections


def test_integrands_are_the_listings(listing):
    families = quadmc.integrands()
    lines = [(f"{f['name']:<24} {f['smoothness']:<14} {f['description']}",
              [f"keys: {f['parameters']}"] if f["parameters"] else []) for f in families]
    assert lines == listing["integrands"]
    for family in families:
        assert isinstance(family["vector_keys"], list) and isinstance(family["scalar_keys"], list)
    genz = next(f for f in families if f["name"] == "genz_gaussian")
    assert (genz["vector_keys"], genz["scalar_keys"], genz["dimension"]) == (["a", "u"], [], None)
    assert genz["string_keys"] == {"coefficient_decay": ["none", "quadratic", "exponential"]}
    assert next(f for f in families if f["name"] == "sqrt")["string_keys"] == {}


def test_methods_are_the_listings(listing):
    methods = quadmc.methods()
    lines = [(f"{m['name']:<30} {m['kind']:<13} {m['description']}",
              ["control = " + " | ".join(m["controls"])]
              + [f"{key} = {meaning}" for key, meaning in m["options"].items()]) for m in methods]
    assert lines == listing["methods"]
    assert {"deterministic", "randomized"} == {m["kind"] for m in methods}


def test_point_sets_are_the_listings(listing):
    # A set with a largest s states it on a line of its own.
    lines = [(f"{p['name']:<30} {p['description']}",
              [f"s ≤ {p['max_dimension']}"] if p["max_dimension"] is not None else [])
             for p in quadmc.point_sets()]
    # The listing ends with external_points, a point_set of importance and the irradiance methods
    # read from the user's files (methods/registry.hpp), which quadmc.points cannot generate.
    assert lines == listing["point sets"][:-1]
    assert listing["point sets"][-1][0].startswith("external_points ")

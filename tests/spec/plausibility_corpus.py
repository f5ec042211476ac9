"""Real objects in SI, for the unit-slip corpus test (tests/spec/test_plausibility_corpus.py).

Each object: (name, shape, sizes in metres, mass in kg, where the numbers come from). Shapes:
``box`` (x, y, z), ``cylinder`` (radius, length), ``sphere`` (radius); a list of such parts for
an object of several. Masses are published figures or a handbook density times the volume;
bodies that are mostly air (a satellite bus, a car, a ship) are one solid of their outside
size and their real mass, as an author sketching them would write them.
"""

from __future__ import annotations

import math

STEEL, ALUMINIUM, COPPER, LEAD, GOLD, TUNGSTEN, OSMIUM = 7850, 2700, 8960, 11340, 19300, 19300, 22590


def box_mass(x, y, z, density):
    return x * y * z * density


def cylinder_mass(radius, length, density):
    return math.pi * radius**2 * length * density


def sphere_mass(radius, density):
    return 4 / 3 * math.pi * radius**3 * density


OBJECTS = [
    ("1U CubeSat", "box", (0.1, 0.1, 0.1135), 1.33, "CubeSat spec: up to 1.33 kg"),
    ("satellite bus", "box", (2.0, 2.0, 2.0), 500.0, "a 500 kg smallsat bus, 2 m cube"),
    ("fuselage section", "cylinder", (3.0, 12.0), 40000.0, "wide-body barrel, 6 m across"),
    ("rocket first stage", "cylinder", (1.83, 42.0), 25600.0, "Falcon 9 stage 1, dry"),
    ("space station module", "cylinder", (2.1, 8.5), 12000.0, "pressurised module"),
    ("foam block", "box", (1.0, 0.5, 0.2), 2.5, "25 kg/m³ polyurethane foam"),
    ("EPS packing block", "box", (0.3, 0.2, 0.1), box_mass(0.3, 0.2, 0.1, 15), "EPS 15 kg/m³"),
    ("aerogel tile", "box", (0.1, 0.1, 0.02), box_mass(0.1, 0.1, 0.02, 100), "silica aerogel 100 kg/m³"),
    ("balsa plank", "box", (0.1, 0.01, 1.0), 0.15, "balsa 150 kg/m³"),
    ("cork stopper", "cylinder", (0.012, 0.044), cylinder_mass(0.012, 0.044, 240), "cork 240 kg/m³"),
    ("lead brick", "box", (0.2, 0.1, 0.05), box_mass(0.2, 0.1, 0.05, LEAD), "lead 11340 kg/m³"),
    ("lead shot", "sphere", (0.001,), sphere_mass(0.001, LEAD), "2 mm pellet"),
    ("osmium cube", "box", (0.01, 0.01, 0.01), box_mass(0.01, 0.01, 0.01, OSMIUM), "osmium 22590 kg/m³"),
    ("gold bar", "box", (0.25, 0.07, 0.04), 12.4, "400 oz bar, as a box"),
    ("tungsten counterweight", "cylinder", (0.01, 0.02), cylinder_mass(0.01, 0.02, TUNGSTEN), "W"),
    ("1 euro coin", "cylinder", (0.011625, 0.00233), 0.0075, "ECB: 23.25 mm, 2.33 mm, 7.5 g"),
    ("US quarter", "cylinder", (0.012130, 0.00175), 0.00567, "US Mint: 24.26 mm, 1.75 mm, 5.67 g"),
    ("gold coin", "cylinder", (0.0163, 0.00284), 0.0339, "Krugerrand: 32.6 mm, 33.9 g"),
    ("hair-thin copper wire", "cylinder", (25e-6, 1.0), cylinder_mass(25e-6, 1.0, COPPER), "50 µm"),
    ("paperclip wire", "cylinder", (0.0005, 0.1), cylinder_mass(0.0005, 0.1, STEEL), "1 mm steel"),
    ("sewing needle", "cylinder", (0.0004, 0.04), cylinder_mass(0.0004, 0.04, STEEL), "steel"),
    ("guitar string", "cylinder", (0.000127, 0.65), cylinder_mass(0.000127, 0.65, STEEL), "0.010 in"),
    ("ship hull", "box", (300.0, 40.0, 25.0), 1.0e8, "100,000 t displacement"),
    ("oil tanker", "box", (330.0, 60.0, 30.0), 3.0e8, "VLCC, loaded"),
    ("shipping container", "box", (12.19, 2.44, 2.59), 3750.0, "40 ft, empty"),
    ("car", "box", (4.5, 1.8, 1.5), 1500.0, "a saloon"),
    ("truck", "box", (12.0, 2.5, 3.5), 15000.0, "a rigid lorry"),
    ("wind turbine blade", "box", (60.0, 3.0, 1.0), 15000.0, "a 60 m blade"),
    ("steel ball bearing", "sphere", (0.005,), sphere_mass(0.005, STEEL), "10 mm ball"),
    ("bowling ball", "sphere", (0.108,), 7.26, "16 lb ball"),
    ("basketball", "sphere", (0.12,), 0.62, "size 7"),
    ("tennis ball", "sphere", (0.0335,), 0.058, "ITF"),
    ("ping-pong ball", "sphere", (0.02,), 0.0027, "ITTF"),
    ("golf ball", "sphere", (0.02135,), 0.0459, "R&A"),
    ("glass marble", "sphere", (0.008,), sphere_mass(0.008, 2500), "glass"),
    ("clay brick", "box", (0.215, 0.1025, 0.065), 2.3, "UK brick"),
    ("concrete block", "box", (0.44, 0.215, 0.1), 10.0, "hollow block"),
    ("oak beam", "box", (0.1, 0.2, 4.0), box_mass(0.1, 0.2, 4.0, 700), "oak 700 kg/m³"),
    ("granite slab", "box", (2.0, 1.0, 0.03), box_mass(2.0, 1.0, 0.03, 2700), "granite"),
    ("steel I-beam", "box", (0.3, 0.15, 6.0), 252.0, "42 kg/m section, as its bounding box"),
    ("aluminium extrusion", "box", (0.04, 0.04, 1.0), 1.5, "hollow profile, as its bounding box"),
    ("flywheel", "cylinder", (0.25, 0.05), cylinder_mass(0.25, 0.05, STEEL), "steel disc"),
    ("water tank", "box", (10.0, 5.0, 2.0), 1.0e5, "full of water"),
    ("ice cube", "box", (0.03, 0.03, 0.03), box_mass(0.03, 0.03, 0.03, 917), "ice"),
    ("concrete pillar", "cylinder", (0.3, 3.0), cylinder_mass(0.3, 3.0, 2400), "concrete"),
    ("water bottle", "cylinder", (0.035, 0.22), 0.52, "0.5 l, full"),
    ("smartphone", "box", (0.147, 0.0715, 0.0078), 0.171, "a phone"),
    ("laptop", "box", (0.30, 0.21, 0.016), 1.3, "a 13 in laptop"),
    ("AA battery", "cylinder", (0.00725, 0.0505), 0.023, "alkaline AA"),
    ("brass nut", "cylinder", (0.005, 0.005), cylinder_mass(0.005, 0.005, 8500), "brass"),
    ("titanium bolt", "cylinder", (0.004, 0.03), cylinder_mass(0.004, 0.03, 4430), "Ti-6Al-4V"),
    ("pencil", "cylinder", (0.0035, 0.175), 0.006, "a pencil"),
    ("violin", "box", (0.6, 0.21, 0.1), 0.45, "as its bounding box"),
    ("guitar", "box", (1.0, 0.35, 0.1), 3.5, "as its bounding box"),
    ("bicycle wheel", "cylinder", (0.35, 0.04), 1.0, "as a disc"),
    ("bicycle frame", "box", (1.0, 0.1, 0.6), 2.0, "as its bounding box"),
    ("human body", "cylinder", (0.15, 1.75), 70.0, "as a cylinder"),
    ("robot arm link", "cylinder", (0.04, 0.4), 2.0, "aluminium tube as a cylinder"),
    ("aluminium rod", "cylinder", (0.02, 0.5), cylinder_mass(0.02, 0.5, ALUMINIUM), "6061"),
    ("copper busbar", "box", (0.01, 0.05, 0.5), box_mass(0.01, 0.05, 0.5, COPPER), "copper"),
    ("propeller blade", "box", (0.25, 0.02, 0.005), 0.012, "drone propeller"),
    (
        "quadcopter",
        [
            ("hub", "box", (0.15, 0.15, 0.05), 0.8),
            ("arm", "cylinder", (0.01, 0.2), 0.025),
            ("motor", "cylinder", (0.014, 0.03), 0.05),
        ],
        None,
        None,
        "a 450 mm quadcopter: hub, an arm, a motor",
    ),
    (
        "satellite with panels",
        [
            ("bus", "box", (1.0, 1.0, 1.2), 180.0),
            ("solar panel", "box", (2.0, 1.0, 0.03), 12.0),
            ("antenna", "cylinder", (0.3, 0.05), 4.0),
        ],
        None,
        None,
        "a small satellite",
    ),
    # FIRST_ADDED_LATER and every object after it were added with the rule already set
    # (issue 26, second round) and are measured apart as a hold-out:
    ("2 euro coin", "cylinder", (0.012875, 0.0022), 0.0085, "ECB: 25.75 mm, 2.2 mm, 8.5 g"),
    ("US penny", "cylinder", (0.009525, 0.00152), 0.0025, "US Mint: 19.05 mm, 1.52 mm, 2.5 g"),
    ("hex key", "cylinder", (0.002, 0.06), cylinder_mass(0.002, 0.06, STEEL), "4 mm steel, as a rod"),
    ("aluminium plate", "box", (0.3, 0.2, 0.01), box_mass(0.3, 0.2, 0.01, ALUMINIUM), "6061 plate"),
    ("brass rod", "cylinder", (0.01, 0.3), cylinder_mass(0.01, 0.3, 8500), "20 mm brass"),
    ("copper pipe", "cylinder", (0.011, 1.0), 0.53, "22 mm x 0.9 mm tube, as a cylinder"),
    ("car tyre", "cylinder", (0.32, 0.2), 9.0, "205/55 R16, as a disc"),
    ("football", "sphere", (0.11,), 0.43, "FIFA size 5"),
    ("soda can", "cylinder", (0.033, 0.122), 0.35, "330 ml, full"),
    ("refrigerator", "box", (0.6, 0.65, 1.8), 70.0, "a fridge-freezer"),
    ("washing machine", "box", (0.6, 0.6, 0.85), 70.0, "front loader"),
    ("city bus", "box", (12.0, 2.55, 3.2), 12000.0, "12 m bus, empty"),
    ("Hubble Space Telescope", "cylinder", (2.1, 13.2), 11110.0, "NASA: 13.2 m, 4.2 m, 11,110 kg"),
    ("3U CubeSat", "box", (0.1, 0.1, 0.3405), 4.0, "CubeSat spec: up to 4 kg"),
    ("kettlebell", "sphere", (0.105,), 16.0, "16 kg cast iron, as a ball"),
    ("anvil", "box", (0.6, 0.15, 0.3), 100.0, "100 kg anvil, as its bounding box"),
    ("paving slab", "box", (0.6, 0.6, 0.05), box_mass(0.6, 0.6, 0.05, 2400), "concrete"),
    ("plywood sheet", "box", (2.44, 1.22, 0.018), box_mass(2.44, 1.22, 0.018, 600), "plywood 600 kg/m³"),
    ("pine stud", "box", (0.038, 0.089, 2.4), box_mass(0.038, 0.089, 2.4, 500), "2x4, pine 500 kg/m³"),
    ("silver bar", "box", (0.118, 0.052, 0.016), 1.0, "1 kg bar, as a box"),
    ("cast iron pan", "cylinder", (0.13, 0.05), 2.5, "skillet, as a disc"),
    ("LEGO brick", "box", (0.0318, 0.0158, 0.0096), 0.0023, "2x4 brick, body only"),
    ("keyboard", "box", (0.44, 0.13, 0.03), 0.9, "a desktop keyboard"),
    ("wind turbine nacelle", "box", (20.0, 8.0, 8.0), 390000.0, "a 8 MW nacelle"),
    ("pallet", "box", (1.2, 0.8, 0.144), 25.0, "EUR pallet"),
    ("upright piano", "box", (1.5, 0.6, 1.3), 230.0, "as its bounding box"),
    ("lead sinker", "sphere", (0.006,), sphere_mass(0.006, LEAD), "12 mm ball"),
    ("steel washer", "cylinder", (0.005, 0.001), cylinder_mass(0.005, 0.001, STEEL), "M5, as a disc"),
    ("glass pane", "box", (1.0, 1.2, 0.004), box_mass(1.0, 1.2, 0.004, 2500), "4 mm float glass"),
    ("hockey puck", "cylinder", (0.0381, 0.0254), 0.17, "NHL: 3 in, 1 in, 6 oz"),
    ("cricket ball", "sphere", (0.036,), 0.16, "MCC: 72 mm, 160 g"),
    ("dumbbell plate", "cylinder", (0.225, 0.03), 20.0, "20 kg cast iron plate, as a disc"),
    ("submarine", "cylinder", (6.5, 110.0), 7.0e6, "7,000 t attack submarine"),
    # SECOND_ADDED_LATER and every object after it were added (issue 26, third round) before the
    # rule was changed again, and are measured apart as a second hold-out:
    (
        "claw hammer",
        [
            ("head", "box", (0.11, 0.025, 0.03), 0.454),
            ("handle", "cylinder", (0.015, 0.3), 0.2),
        ],
        None,
        None,
        "16 oz head, hickory handle",
    ),
    ("adjustable wrench", "box", (0.25, 0.06, 0.015), 0.45, "250 mm wrench, as its bounding box"),
    (
        "screwdriver",
        [
            ("handle", "cylinder", (0.015, 0.1), 0.05),
            ("shaft", "cylinder", (0.003, 0.1), cylinder_mass(0.003, 0.1, STEEL)),
        ],
        None,
        None,
        "plastic handle, 6 mm steel shaft",
    ),
    ("baseball", "sphere", (0.0373,), 0.145, "MLB: 9 in round, 5 oz"),
    ("volleyball", "sphere", (0.105,), 0.27, "FIVB: 65-67 cm round, 260-280 g"),
    ("shot put", "sphere", (0.06,), 7.26, "men's shot: 7.26 kg, 110-130 mm"),
    ("baseball bat", "cylinder", (0.033, 0.84), 0.9, "33 in bat, as a cylinder"),
    ("motorcycle", "box", (2.1, 0.8, 1.2), 200.0, "a 200 kg motorcycle, as its bounding box"),
    ("car engine", "box", (0.7, 0.6, 0.6), 200.0, "a petrol engine with its ancillaries"),
    ("alloy wheel", "cylinder", (0.21, 0.18), 10.0, "17 in rim, as a disc"),
    ("brake disc", "cylinder", (0.15, 0.028), 7.0, "300 mm vented disc, as a disc"),
    ("glass beaker", "cylinder", (0.053, 0.145), 0.42, "1 l borosilicate beaker, empty, as a cylinder"),
    ("1 kg calibration weight", "cylinder", (0.024, 0.0691), 1.0, "OIML stainless cylinder"),
    ("optical breadboard", "box", (0.6, 0.45, 0.0127), 8.6, "600 x 450 mm aluminium, tapped holes"),
    ("microscope", "box", (0.3, 0.2, 0.4), 8.0, "a lab microscope, as its bounding box"),
    ("Rubik's cube", "box", (0.057, 0.057, 0.057), 0.1, "3x3 cube"),
    ("tennis racket", "box", (0.685, 0.27, 0.025), 0.3, "as its bounding box"),
    ("office chair", "box", (0.65, 0.65, 1.1), 15.0, "as its bounding box"),
    ("dining table", "box", (1.6, 0.9, 0.75), 40.0, "as its bounding box"),
    ("bookcase", "box", (0.8, 0.28, 2.02), 37.0, "80 x 28 x 202 cm flat-pack bookcase"),
    ("car battery", "box", (0.278, 0.175, 0.19), 18.0, "lead-acid, 70 Ah"),
    ("railway wheel", "cylinder", (0.46, 0.14), 380.0, "920 mm freight wheel, as a disc"),
    ("steel rail", "box", (0.15, 0.172, 1.0), 60.0, "1 m of 60 kg/m rail, as its bounding box"),
    ("water cooler bottle", "cylinder", (0.135, 0.49), 19.5, "5 US gal, full"),
    ("fire extinguisher", "cylinder", (0.08, 0.5), 10.0, "6 kg powder, full, as a cylinder"),
    ("skateboard", "box", (0.8, 0.21, 0.11), 3.5, "deck, trucks and wheels, as its bounding box"),
    ("LiPo battery", "box", (0.138, 0.043, 0.035), 0.5, "4S 5000 mAh pack"),
    ("gas cylinder", "cylinder", (0.115, 1.5), 60.0, "50 l, 200 bar steel cylinder, empty"),
    ("microSD card", "box", (0.015, 0.011, 0.001), 0.0004, "SD Association: 15 x 11 x 1 mm"),
    ("die-cast toy car", "box", (0.07, 0.03, 0.025), 0.035, "1:64 scale, as its bounding box"),
    ("nail", "cylinder", (0.0016, 0.075), cylinder_mass(0.0016, 0.075, STEEL), "75 mm wire nail"),
    ("M8 bolt", "cylinder", (0.004, 0.04), cylinder_mass(0.004, 0.04, STEEL), "steel, as a rod"),
]

FIRST_ADDED_LATER = "2 euro coin"
"""The first object of the hold-out: it and every object after it in OBJECTS."""

SECOND_ADDED_LATER = "claw hammer"
"""The first object of the second hold-out (added before the rule's third-round change)."""

SLIPS = {
    # the units an author drew in, and the hint that names them
    "mm/g": ({"length": "mm", "mass": "g"}, "add units: {length: mm, mass: g}"),
    "mm/kg": ({"length": "mm", "mass": "kg"}, "add units: {length: mm}"),
    "cm/g": ({"length": "cm", "mass": "g"}, "add units: {length: cm, mass: g}"),
    "in/lb": ({"length": "in", "mass": "lb"}, "add units: {length: in, mass: lb}"),
}
LENGTH_M = {"m": 1.0, "mm": 0.001, "cm": 0.01, "in": 0.0254}
MASS_KG = {"kg": 1.0, "g": 0.001, "lb": 0.45359237}


def significant(value: float, digits: int | None) -> float:
    """``value`` rounded to ``digits`` significant digits (unchanged for None or 0)."""
    if not digits or not value:
        return value
    return round(value, digits - 1 - math.floor(math.log10(abs(value))))


def _part(name, shape, sizes, mass, length, mass_unit, digits=None):
    s = [significant(v / LENGTH_M[length], digits) for v in sizes]
    m = significant(mass / MASS_KG[mass_unit], digits)
    if shape == "box":
        return {"name": name, "shape": "box", "center": [0, 0, 0], "size": s, "mass": m}
    if shape == "cylinder":
        return {
            "name": name,
            "shape": "cylinder",
            "radius": s[0],
            "start": [0, 0, 0],
            "end": [0, 0, s[1]],
            "mass": m,
        }
    return {"name": name, "shape": "sphere", "radius": s[0], "center": [0, 0, 0], "mass": m}


def spec(entry, length="m", mass="kg", digits=None):
    """The spec of a corpus object with its numbers written in ``length`` and ``mass``, no
    ``units:`` block; with ``digits``, every size and mass rounded to that many significant
    digits, as a person writes them (conversions no longer exact, handbook densities no longer
    met to 0.1 %)."""
    name, shape, sizes, kilograms, _ = entry
    if isinstance(shape, list):
        parts = [_part(*p, length, mass, digits) for p in shape]
        for i, part in enumerate(parts):  # side by side, apart
            part["name"] = f"{part['name']}"
            if "center" in part:
                part["center"] = [3.0 * i / LENGTH_M[length], 0, 0]
            else:
                part["start"], part["end"] = (
                    [3.0 * i / LENGTH_M[length], 0, 0],
                    [
                        3.0 * i / LENGTH_M[length],
                        0,
                        part["end"][2],
                    ],
                )
        return {"name": name, "parts": parts}
    return {"name": name, "parts": [_part(name, shape, sizes, kilograms, length, mass, digits)]}

"""Read monitors.csv by column name.

The header of monitors.csv gives each column's unit after its name,
"kinetic_energy[J/m]" (README, Output); columns without a unit (step,
lost_particles, the Eq. (30) ratios) have none. DictReader(f) is
csv.DictReader with the units stripped from the names, so that scripts
look columns up as row["kinetic_energy"]; units(f) gives {name: unit}.
It reads files written before the header had units the same way.
"""

import csv
import re

_UNIT = re.compile(r"^(.*?)\[([^\]]*)\]$")


def split_header(name):
    """'kinetic_energy[J/m]' -> ('kinetic_energy', 'J/m'); no unit: ''."""
    m = _UNIT.match(name.strip())
    return (m.group(1), m.group(2)) if m else (name.strip(), "")


def column_name(name):
    """The column's name without its unit."""
    return split_header(name)[0]


def DictReader(f, **kwargs):
    """csv.DictReader over monitors.csv, keyed by the bare column names."""
    reader = csv.DictReader(f, **kwargs)
    if reader.fieldnames is not None:
        reader.fieldnames = [column_name(n) for n in reader.fieldnames]
    return reader


def units(path):
    """{column name: unit} from the header of the monitors.csv at path."""
    with open(path) as f:
        header = next(csv.reader(f))
    return dict(split_header(n) for n in header)

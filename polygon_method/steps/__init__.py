"""The construction steps: one module per kind of hand construction.

Each module holds everything about its kind: how the compiler recognises it in the
scene's constraint graph (``recognise``), its position formula and branch, its velocity and
acceleration as plain functions on floats or numpy arrays, its condition and the words for
why it is singular or at a limit, what it draws on the polygons (``construction``) and its
line of the step table (``position_words``).

============ ===========================================================================
crank        the driving crank's tip
block        a driving block on a fixed guide, its place along it the motion's parameter
collar       a driving collar on a rod pivoted on the frame, pinned to a crank: its place on
             the rod the parameter, its sliding relative to the rod given (Coriolis)
second crank a second driven crank (two degrees of freedom): its own angle and speed
second collar a collar sliding along the crank as the second input: its sliding given
carried      a point on a known link or plate (the image point, similar triangles)
slider       RRP: a link and a slider on a fixed path or on a moving link
dyad         RRR: the joint of two links (or plate sides) to two known points
slotted      RPR: a link that a block slides along (slotted lever, Whitworth, swivel)
rolling      a wheel or gear rolling without slip on a line, a fixed circle or a gear
wheel_centre the centre of a wheel rolling on a line, found from a link pinned to it
rack         a rack (a block on a fixed path) driven by a pinion without slip
peg          a pin in two slots: where a fixed slot and a slotted link, or two slotted
             links, cross (two sliding pairs, a Coriolis component in each moving slot)
yoke         a translating slotted yoke on a fixed path, placed by a known pin in its slot
             (the Scotch yoke)
cylinder     a hydraulic cylinder between two known points: length, extension rate, omega
triad        class-III group: a plate whose three vertices are each linked to a known point
             (three points at once: Newton on the loop equations; Goodman's auxiliary point)
============ ===========================================================================

Adding a kind: write its module (a frozen ``Step`` subclass and a ``recognise(g, name)``
function) and add it to :data:`TIERS`.
"""

from . import carried, dyad, peg, rack, rolling, slider, slotted, triad, wheel_centre, yoke
from .block import BlockDriver
from .base import (
    Construction,
    Context,
    DirectionLine,
    State,
    Step,
    Vector,
    image_label,
    image_name,
    pole_text,
)
from .carried import Carried
from .crank import Crank
from .cylinder import CylinderStep
from .dyad import Dyad
from .rolling import RollingWheel
from .peg import Peg, slot_labels
from .yoke import Yoke
from .slider import SliderDyad
from .slotted import SlottedLink, under_label
from .triad import Triad

#: the recognisers the compiler tries, tier by tier: for each unknown point (in the scene's
#: order) every kind of the first tier in turn; the next tier only when no point of the
#: tiers before can be found. The driver (a crank, or a block on a fixed guide) is the plan's
#: first step and is not recognised.
TIERS = (
    (
        rolling.recognise,
        wheel_centre.recognise,
        rack.recognise,
        carried.recognise,
        slider.recognise,
        dyad.recognise,
        peg.recognise,
        yoke.recognise,
    ),
    (slotted.recognise,),
    (triad.recognise,),
)

#: the scene's table (a :class:`~polygon_method.scene.Scene` attribute) without which a
#: first-tier recogniser finds nothing: the compiler leaves it out for a scene whose table
#: is empty (a linkage of pins alone tries the carried points and the dyad only). A
#: recogniser not listed is always tried.
NEEDS = {
    rolling.recognise: "rolling",
    wheel_centre.recognise: "rolling",
    rack.recognise: "rolling",
    carried.recognise: "points",
    slider.recognise: "sliders",
    peg.recognise: "sliders",
    yoke.recognise: "sliders",
}

__all__ = [
    "TIERS",
    "NEEDS",
    "Step",
    "Context",
    "State",
    "Crank",
    "BlockDriver",
    "Dyad",
    "SliderDyad",
    "SlottedLink",
    "Carried",
    "CylinderStep",
    "RollingWheel",
    "Triad",
    "Peg",
    "Yoke",
    "Construction",
    "Vector",
    "DirectionLine",
    "image_label",
    "image_name",
    "pole_text",
    "under_label",
    "slot_labels",
]

"""The signs and signals the generator places, per country: type codes from the country's sign catalogue.

OpenDRIVE names a sign by ``country``, ``type`` and ``subtype`` (14.1, 14.8): the codes are the country's own, and
signals that no country numbers (traffic lights) come from the standard's signal reference with
``country="OpenDRIVE"`` (14.1: "They can be used with the appropriate @type, @subtype and the @country="OpenDRIVE"").

Germany (``DE``) is the country of the standard's own examples (14.1: sign 274, a speed limit, ``country="DE"``) and
of the numbering CARLA's and esmini's readers know (CARLA's ``SignalType``: 205 yield, 206 stop, 294 stop line). Its
catalogue is the Straßenverkehrs-Ordnung's sign list (Anlage 1-3 StVO): 205 "Vorfahrt gewähren" (yield), 206 "Halt.
Vorfahrt gewähren" (stop), 306 "Vorfahrtstraße" (priority road), 294 "Haltlinie" (stop line, a road marking with a
sign number), and at roundabouts 215 "Kreisverkehr" (roundabout, under the yield sign on every entry) and 341
"Wartelinie" (yield line, the broken line where entering traffic waits). Traffic lights are the signal reference's
1000001 (three lights, red-yellow-green, for vehicles). Another country is one more :class:`Catalogue` entry in
:data:`COUNTRIES`.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SignType:
    """One kind of sign or signal: what ``<signal>`` says about it, and its size (m) for rendering tools."""

    country: str
    type: str
    subtype: str
    name: str
    dynamic: bool = False
    width: float = 0.6
    height: float = 0.6
    z_offset: float = 2.0  #: height of the sign's bottom edge above the road (m)


#: The signal reference's vehicle traffic light: three lights, red, yellow, green (``country="OpenDRIVE"``).
TRAFFIC_LIGHT = SignType("OpenDRIVE", "1000001", "-1", "traffic light", True, 0.35, 0.95, 2.5)


@dataclass(frozen=True)
class Catalogue:
    """The signs of one country's catalogue the generator uses."""

    country: str
    stop: SignType
    yield_: SignType
    priority_road: SignType
    stop_line: SignType  #: a road marking across the stopping lanes (height 0, z offset 0)
    roundabout: SignType  #: on every entry of a roundabout, under the yield sign
    yield_line: SignType  #: a road marking across a roundabout's entry lanes (height 0, z offset 0)
    traffic_light: SignType = TRAFFIC_LIGHT


#: Country code -> catalogue.
COUNTRIES: dict[str, Catalogue] = {
    "DE": Catalogue(
        "DE",
        stop=SignType("DE", "206", "-1", "stop"),
        yield_=SignType("DE", "205", "-1", "yield", width=0.9, height=0.8),
        priority_road=SignType("DE", "306", "-1", "priority road"),
        stop_line=SignType("DE", "294", "-1", "stop line", width=0.0, height=0.0, z_offset=0.0),
        roundabout=SignType("DE", "215", "-1", "roundabout"),
        yield_line=SignType("DE", "341", "-1", "yield line", width=0.0, height=0.0, z_offset=0.0),
    ),
}

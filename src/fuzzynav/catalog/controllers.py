"""Controllers by name: ``fuzzynav run SCENARIO --controller NAME`` looks names up here.

Each controller is one :class:`~fuzzynav.catalog.specs.ControllerSpec`, registered once below
with :func:`register_controller` (a name or alias taken twice is an error). Its factory is a
``"module:function"`` string, imported only when the controller is made, so listing names stays
cheap. An installed distribution adds its own controllers through the entry point group
``fuzzynav.controllers`` (an object: a spec or a list of specs), read on first use::

    [project.entry-points."fuzzynav.controllers"]
    my-navigator = "my_package.navigator:NAVIGATOR"
"""

from __future__ import annotations

import re

from fuzzynav import validation
from fuzzynav.catalog.specs import SENSES, ControllerSpec
from fuzzynav.control.base import Controller
from fuzzynav.errors import InputError
from fuzzynav.lookup import Registry, load

CONTROLLERS: Registry[ControllerSpec] = Registry("controller", "--controller", ControllerSpec,
                                                group="fuzzynav.controllers")


def register_controller(spec: ControllerSpec) -> ControllerSpec:
    """Add ``spec`` to the controllers (a ``ValueError`` when its name or an alias is taken)."""
    return CONTROLLERS.register(spec)


GSB = {"gsb": "goal-seeking"}
TWO = {**GSB, "oab": "obstacle-avoidance"}
FIVE = {**GSB, "foa": "foa", "roa": "roa", "loa": "loa", "vrb": "vrb"}
GOAL, TRACK = ("goal",), ("path", "target")

register_controller(ControllerSpec(
    "goal-seeking", "fuzzynav.control.goal_seeking:make", "goal seeking alone (35 rules)",
    "thesis Table IV.1, §IV.5.1", GOAL, roles=GSB))
register_controller(ControllerSpec(
    "fuzzy-5b", "fuzzynav.control.through_gaps:fuzzy_5b_gap_robust",
    "the default navigator: the five behaviours on a lidar, steering through the gap that fits the body, "
    "aimed along a route planned for the car (hybrid A* with reverse arcs) on what it has sensed; recovery, "
    "loop escape, a speed set by the room ahead, and yielding to moving obstacles its tracks predict; what each "
    "version added, and the options that give the earlier ones: *Versions of fuzzy-5b* in docs/guide/controllers.md",
    "thesis §IV.7; Dolgov et al. 2008; Fox et al. 1997; Smith 1957; Koenig & Likhachev 2002; Elfes 1989; "
    "Fiorini & Shiller 1998; Agrawal & Sreenath 2017", GOAL,
    "lidar", roles=FIVE, aliases=("fuzzy-5b-gap-robust",), version=15,
    brief="the default navigator: five behaviours, lidar, planned route"))
register_controller(ControllerSpec(
    "fuzzy-5b-yield", "fuzzynav.control.yielding:make",
    "fuzzy-5b under a fuzzy yield / evade layer on the time to collision with moving obstacles, read from two "
    "lidar scans (for dynamic worlds)", "this package; time to collision after Lee 1976", GOAL, "lidar",
    brief="fuzzy-5b under a fuzzy yield / evade layer (dynamic worlds)"))
register_controller(ControllerSpec(
    "fuzzy-5b-yield-tracks", "fuzzynav.control.yielding:make_tracked",
    "fuzzy-5b-yield that also tracks moving obstacles over successive scans and predicts them out of view "
    "(time to collision by velocity obstacles, for threats abeam and behind), round the default fuzzy-5b; "
    "version 1 ran round fuzzy-5b at the thesis' speeds, remembering moving obstacles wherever seen",
    "this package; Fiorini & Shiller 1998", GOAL, "lidar", version=2,
    brief="fuzzy-5b-yield that also tracks moving obstacles"))
register_controller(ControllerSpec(
    "fuzzy-5b-rays", "fuzzynav.control.robust:fuzzy_5b",
    "fuzzy-5b-thesis with recovery (backing out) and loop escape (boundary following), on the 7 range sensors: "
    "version 1 of fuzzy-5b", "thesis §IV.7; Lumelsky & Stepanov 1987", GOAL, "rays", roles=FIVE,
    brief="fuzzy-5b-thesis with recovery and loop escape, 7 rays"))
register_controller(ControllerSpec(
    "fuzzy-2b", "fuzzynav.control.robust:fuzzy_2b",
    "fuzzy-2b-thesis with recovery (backing out) and loop escape (boundary following), on the 7 range sensors",
    "thesis Table IV.2, Fig IV.9; Lumelsky & Stepanov 1987", GOAL, "rays", roles=TWO,
    brief="fuzzy-2b-thesis with recovery and loop escape, 7 rays"))
register_controller(ControllerSpec(
    "fuzzy-2b-thesis", "fuzzynav.control.robust:fuzzy_2b_thesis",
    "goal seeking + obstacle avoidance by distance and angle of the nearest obstacle, switched, as published",
    "thesis Table IV.2, Fig IV.9", GOAL, "rays", roles=TWO, brief="goal seeking + obstacle avoidance, as published"))
register_controller(ControllerSpec(
    "fuzzy-5b-thesis", "fuzzynav.control.robust:fuzzy_5b_thesis",
    "the five behaviours GSB, FOA, ROA, LOA, VRB with the supervisor of Fig IV.16, as published",
    "thesis §IV.7", GOAL, "rays", roles=FIVE, brief="the five behaviours and their supervisor, as published"))
register_controller(ControllerSpec(
    "fuzzy-2b-layered", "fuzzynav.control.robust:fuzzy_2b_layered",
    "fuzzy-2b-thesis with this package's layers: anti-orbit guard, turning room, safety stop and hysteresis",
    "thesis Table IV.2, Fig IV.9; this package's layers", GOAL, "rays", roles=TWO,
    brief="fuzzy-2b-thesis with this package's layers"))
register_controller(ControllerSpec(
    "fuzzy-5b-layered", "fuzzynav.control.robust:fuzzy_5b_layered",
    "fuzzy-5b-thesis with this package's layers: anti-orbit guard, turning room, safety stop and hysteresis",
    "thesis §IV.7; this package's layers", GOAL, "rays", roles=FIVE,
    brief="fuzzy-5b-thesis with this package's layers"))
register_controller(ControllerSpec(
    "goal-seeking-guarded", "fuzzynav.control.goal_seeking:make_guarded",
    "goal-seeking with this package's anti-orbit guard", "thesis Table IV.1; this package's layer", GOAL,
    roles=GSB))
register_controller(ControllerSpec(
    "fuzzy-2b-gap", "fuzzynav.control.avoidance:make_gap",
    "fuzzy-2b-thesis on a lidar, steering through the widest gap that fits; no recovery, no route (opt-in)",
    "thesis Table IV.2", GOAL, "lidar", roles=TWO,
    brief="fuzzy-2b-thesis on a lidar, through the widest gap that fits"))
register_controller(ControllerSpec(
    "fuzzy-5b-gap", "fuzzynav.control.five_behaviours:make_gap",
    "fuzzy-5b-thesis on a lidar, steering through the widest gap that fits; no recovery, no route "
    "(the core of fuzzy-5b)", "thesis §IV.7", GOAL, "lidar", roles=FIVE,
    brief="fuzzy-5b-thesis on a lidar, through the widest gap that fits"))
register_controller(ControllerSpec(
    "wall-follow", "fuzzynav.control.wall_following:make", "hand-made fuzzy wall follower",
    "thesis Table VI.2", GOAL, "rays", goal_directed=False, roles={"wall": "wall-follow"}))
register_controller(ControllerSpec(
    "fuzzy-tracker", "fuzzynav.control.tracking:fuzzy_tracker", "fuzzy path / target tracker (25 rules)",
    "thesis Table V.1, §V.3.1", TRACK, roles={"tracker": "tracking"}))
register_controller(ControllerSpec(
    "neural-tracker", "fuzzynav.learn.tasks.trackers:neural_tracker",
    "MLP inverse-model tracker, trained on the fly", "thesis §V.3.2", TRACK))
register_controller(ControllerSpec(
    "anfis-tracker", "fuzzynav.learn.tasks.trackers:anfis_tracker",
    "ANFIS tracker, 1 input, 5 MFs, trained on the fly", "thesis §V.3.5", TRACK))
register_controller(ControllerSpec(
    "pure-pursuit", "fuzzynav.control.baselines:pure_pursuit", "pure pursuit baseline", "Coulter 1992", TRACK))
register_controller(ControllerSpec(
    "stanley", "fuzzynav.control.baselines:stanley", "Stanley steering baseline", "Thrun et al. 2006", TRACK))
register_controller(ControllerSpec(
    "dwa", "fuzzynav.control.classic.dwa:make", "Dynamic Window Approach on the 7 range sensors",
    "Fox, Burgard & Thrun 1997", GOAL, "rays"))
register_controller(ControllerSpec(
    "dwa-tracks", "fuzzynav.control.classic.dwa:make_tracked",
    "dwa on a lidar, each arc checked against the moving obstacles tracked over successive scans, moved along "
    "their predicted tracks over the arc's time (the tracker of fuzzy-5b-yield-tracks)",
    "Fox, Burgard & Thrun 1997; Fiorini & Shiller 1998", GOAL, "lidar",
    brief="dwa on a lidar, its arcs checked against tracked obstacles"))
register_controller(ControllerSpec(
    "apf", "fuzzynav.control.classic.apf:make", "artificial potential field on the 7 range sensors",
    "Khatib 1986", GOAL, "rays"))
register_controller(ControllerSpec(
    "vfh", "fuzzynav.control.classic.vfh:make", "VFH+ on the 7 range sensors", "Ulrich & Borenstein 1998",
    GOAL, "rays"))
register_controller(ControllerSpec(
    "vfh-tracks", "fuzzynav.control.classic.vfh:make_tracked",
    "vfh on a lidar, its histogram also holding the moving obstacles tracked over successive scans at their "
    "predicted places over the next 1.5 s (the tracker of fuzzy-5b-yield-tracks)",
    "Borenstein & Koren 1991; Ulrich & Borenstein 1998", GOAL, "lidar",
    brief="vfh on a lidar, its histogram holding tracked obstacles"))
register_controller(ControllerSpec(
    "astar-pp", "fuzzynav.control.classic.astar_pp:make",
    "MAP-AWARE reference: hybrid A* on the inflated map (backward arcs where no forward path exists) + pure "
    "pursuit, planning again from its pose when it leaves the plan; where no arc ahead is clear it backs off, or "
    "takes the clearest only while it stays off the map, or stands (knows the whole map); version 2 drove the "
    "clearest arc ahead there, version 1 planned once",
    "Dolgov et al. 2008; Coulter 1992; Kuwata et al. 2009", GOAL, needs_map=True, version=3,
    brief="MAP-AWARE reference: hybrid A* on the map + pure pursuit"))


def available() -> dict[str, str]:
    """Names of the registered controllers with their one-line descriptions (and sources)."""
    return {name: CONTROLLERS[name].summary for name in sorted(CONTROLLERS)}


def briefs() -> dict[str, str]:
    """Names of the registered controllers with their short line (``fuzzynav run --help``)."""
    return {name: CONTROLLERS[name].short for name in sorted(CONTROLLERS)}


def spec_of(name: str) -> ControllerSpec:
    """The spec registered as ``name`` or under the alias ``name`` (an :class:`InputError` on
    ``--controller`` names close matches)."""
    return CONTROLLERS.find(name)


def scenario_controllers(scenario, source: str) -> tuple[str, ...]:
    """A scenario's own ``controllers`` list, each name known (an unknown one is an
    :class:`InputError` naming the scenario file ``source`` and its place in the list)."""
    for i, name in enumerate(scenario.controllers):
        try:
            spec_of(name)
        except InputError as error:
            raise InputError(error.problem, source=source, field=f"controllers[{i}]") from None
    return scenario.controllers


def make_controller(name: str, **options) -> Controller:
    """Build the controller registered as ``name`` (or under the alias ``name``); a controller
    with aliases carries the name asked for, which its traces and metrics show. A bad option (one
    the controller does not take, or a value its constructor refuses:
    :mod:`fuzzynav.settings`) is an :class:`InputError` naming the controller and the option."""
    validation.text(name, field="name", max_length=200)
    spec = spec_of(name)
    try:
        controller = load(spec.factory)(**options)
    except InputError as error:
        if error.source is not None:
            raise
        raise InputError(error.problem, source=f"{name} options", field=error.field) from None
    except TypeError as error:
        option = re.search(r"(unexpected|multiple values for) (?:keyword )?argument '(\w+)'", str(error))
        if option is None or option[2] not in options:
            raise
        problem = "no such option" if option[1] == "unexpected" else "is set by the controller itself"
        raise InputError(problem, source=f"{name} options", field=option[2]) from None
    if spec.aliases:
        controller.name = name
    return controller


def check_task(name: str, task: str, field: str = "--controller") -> None:
    """An :class:`InputError` on ``field`` unless controller ``name`` can do ``task`` (``goal``,
    ``path`` or ``target``, the scenario's), naming the controllers that can."""
    spec = spec_of(name)
    if task not in spec.tasks:
        able = [other for other in sorted(CONTROLLERS) if task in CONTROLLERS[other].tasks]
        raise InputError(f"{name} cannot do a {task} task (it does: {', '.join(spec.tasks)}); "
                         f"for a {task} task use one of {', '.join(able)}", field=field)


def controller_table() -> str:
    """The controller table of the user guide (docs/guide/controllers.md), in Markdown."""
    rows = ["| name | what it is | source | tasks | reads |", "|---|---|---|---|---|"]
    for name in sorted(CONTROLLERS):
        spec = CONTROLLERS[name]
        names = ", ".join(f"`{each}`" for each in (name, *spec.aliases))
        version = f" (version {spec.version})" if spec.version > 1 else ""
        reads = "**the whole map**" if spec.needs_map else SENSES[spec.sensors]
        rows.append(f"| {names}{version} | {spec.description} | {spec.citation} | {', '.join(spec.tasks)} | {reads} |")
    return "\n".join(rows) + "\n"

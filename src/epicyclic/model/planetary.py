"""The planetary (epicyclic) set: two central members and a carrier.

A set joins three shafts: the first central member (``sun``), the second
central member (``ring``) and the carrier.  Its kinematics and statics depend
only on the stationary ratio

.. math:: i_0 = \\frac{n_\\mathrm{sun} - n_\\mathrm{carrier}}{n_\\mathrm{ring} - n_\\mathrm{carrier}}

and its losses only on the stationary efficiency :math:`\\eta_0` (the
efficiency with the carrier held).  For a set with two external meshes
(Brandenberger's a/b·c/d with two suns) the "ring" is simply the second central
gear.

References
----------
Brandenberger 1952, eq. 1 (written there with the inverse ratio ac/bd).
Queitsch, eqs. 3, 4 and 12 (s = i0).
tec-science, "Willis-Gleichung", "Festgestellter Steg" (i0 = -z_H/z_S).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..errors import ModelError, ToothCountError
from .teeth import COAXIAL_TOLERANCE_TEETH, Teeth, check_double, check_stepped, check_teeth
from .validation import check_efficiency, check_name, check_planets, finite_float

__all__ = ["PlanetarySet", "Teeth", "check_efficiency", "check_name", "check_planets", "finite_float",
           "check_teeth", "COAXIAL_TOLERANCE_TEETH"]


@dataclass(frozen=True)
class PlanetarySet:
    """A planetary set joining three shafts.

    Parameters
    ----------
    name : str
        Element name, unique in the train.
    sun, ring, carrier : str
        Names of the shafts joined to the first central member, the second
        central member and the carrier.
    stationary_ratio : float
        i0 = (n_sun - n_carrier) / (n_ring - n_carrier); negative for a minus
        set, positive for a plus set.  Must not be 0 or 1.
    stationary_efficiency : float, default 1.0
        η0, the efficiency of the set with the carrier held, in (0, 1].
    planets : int, default 3
        Number of planets (shares tooth forces; no effect on kinematics).
    teeth : Teeth, optional
        Tooth counts the ratio came from (gives planet speeds).

    References
    ----------
    Brandenberger 1952, eqs. 1, 2, 3' and 7.

    Examples
    --------
    >>> s = PlanetarySet.simple("P1", sun="in", ring="housing", carrier="out",
    ...                         z_sun=30, z_planet=24, z_ring=78, stationary_efficiency=0.98)
    >>> s.stationary_ratio
    -2.6
    """

    name: str
    sun: str
    ring: str
    carrier: str
    stationary_ratio: float
    stationary_efficiency: float = 1.0
    planets: int = 3
    teeth: Teeth | None = field(default=None)

    def __post_init__(self) -> None:
        owner = f"planetary set {self.name!r}"
        check_name(self.name, "name", "planetary set")
        for role in ("sun", "ring", "carrier"):
            check_name(getattr(self, role), role, owner)
        shafts = (self.sun, self.ring, self.carrier)
        if len(set(shafts)) != 3:
            raise ModelError(
                f"{owner}: sun, ring and carrier must be three different shafts, got "
                f"sun={self.sun!r}, ring={self.ring!r}, carrier={self.carrier!r}. "
                "To lock the set, join two of its shafts with a Clutch instead."
            )
        ratio = self.stationary_ratio
        if finite_float(ratio) is None:
            raise ModelError(f"{owner}: stationary_ratio must be a finite number, got {ratio!r}.")
        if ratio == 0.0 or abs(ratio - 1.0) < 1e-12:
            raise ModelError(
                f"{owner}: stationary_ratio must not be 0 or 1, got {ratio!r} "
                "(0 holds the sun, 1 locks the set: neither is a planetary set)."
            )
        object.__setattr__(self, "stationary_ratio", float(ratio))
        object.__setattr__(
            self,
            "stationary_efficiency",
            check_efficiency(self.stationary_efficiency, "stationary_efficiency", owner),
        )
        check_planets(self.planets, "planets", owner)

    # ------------------------------------------------------------------ constructors
    @classmethod
    def simple(
        cls,
        name: str,
        *,
        sun: str,
        ring: str,
        carrier: str,
        z_sun: int,
        z_planet: int,
        z_ring: int,
        stationary_efficiency: float | None = None,
        mesh_efficiencies: tuple[float, ...] | None = None,
        planets: int = 3,
    ) -> PlanetarySet:
        """A simple sun–planet–ring (minus) set from tooth counts: i0 = -z_ring/z_sun.

        Parameters
        ----------
        name : str
            Element name (unique in the train).
        sun, ring, carrier : str
            The shafts the sun, the ring and the carrier sit on.
        z_sun, z_planet, z_ring : int
            Tooth counts (3 … 1000).  The ring must be coaxial with the sun:
            z_ring = z_sun + 2·z_planet, within ±2 teeth (profile shift).
        stationary_efficiency : float, optional
            η0 in (0, 1], the efficiency with the carrier held; default 1
            (lossless) unless ``mesh_efficiencies`` are given.
        mesh_efficiencies : tuple of float, optional
            (sun–planet, planet–ring), each in (0, 1], combined by product into η0;
            not together with ``stationary_efficiency``.
        planets : int, default 3
            Number of planets (1 … 24): for the planet loads and the geometry
            (equal spacing needs (z_sun + z_ring)/planets whole, checked by
            :func:`~epicyclic.geometry.check_fitting`).

        Returns
        -------
        PlanetarySet

        Raises
        ------
        ToothCountError
            A count that is not a whole number in range, a ring not larger than
            the sun, or counts that cannot mesh coaxially (the message says which
            count to change).
        EfficiencyError
            An efficiency outside (0, 1].

        References
        ----------
        tec-science, "Willis-Gleichung", Standübersetzung i_0; Queitsch, eq. 4.

        Examples
        --------
        >>> p = PlanetarySet.simple("P", sun="in", ring="ring", carrier="out",
        ...                         z_sun=30, z_planet=24, z_ring=78, stationary_efficiency=0.98)
        >>> p.stationary_ratio, p.planets
        (-2.6, 3)
        """
        owner = f"planetary set {name!r}"
        zs = check_teeth(z_sun, "z_sun", owner)
        zr = check_teeth(z_ring, "z_ring", owner)
        if zr <= zs:
            raise ToothCountError(
                f"{owner}: the ring must have more teeth than the sun, got z_ring={zr}, z_sun={zs}. "
                "Swap them, or use PlanetarySet.stepped for two external central gears."
            )
        zp = check_teeth(z_planet, "z_planet", owner)
        mismatch = zr - zs - 2 * zp
        if abs(mismatch) > COAXIAL_TOLERANCE_TEETH:
            raise ToothCountError(
                f"{owner}: tooth counts cannot mesh coaxially: z_ring - z_sun - 2*z_planet = "
                f"{zr} - {zs} - 2*{zp} = {mismatch}, expected 0 (at most ±{COAXIAL_TOLERANCE_TEETH} "
                f"with profile shift). For z_sun={zs} and z_ring={zr} use "
                f"z_planet={(zr - zs) // 2}" + (" (and make z_ring - z_sun even)" if (zr - zs) % 2 else "") + "."
            )
        teeth = Teeth("simple", zs, zr, (zp,))
        return cls(
            name, sun, ring, carrier, teeth.stationary_ratio,
            _combine(stationary_efficiency, mesh_efficiencies, 2, owner), planets, teeth,
        )

    @classmethod
    def double_planet(
        cls,
        name: str,
        *,
        sun: str,
        ring: str,
        carrier: str,
        z_sun: int,
        z_planet_sun: int,
        z_planet_ring: int,
        z_ring: int,
        stationary_efficiency: float | None = None,
        mesh_efficiencies: tuple[float, ...] | None = None,
        planets: int = 3,
    ) -> PlanetarySet:
        """A double-planet (plus) set: sun–planet 1–planet 2–ring, i0 = +z_ring/z_sun.

        The planets must be placeable: planet 1 at (z_sun + z_p1)/2, planet 2 at
        (z_ring − z_p2)/2 and their centre distance (z_p1 + z_p2)/2 (modules) must
        close a triangle, within one module (see :func:`~epicyclic.model.teeth.check_double`).

        Parameters
        ----------
        name : str
            Element name (unique in the train).
        sun, ring, carrier : str
            The shafts the sun, the ring and the carrier sit on.
        z_sun, z_planet_sun, z_planet_ring, z_ring : int
            Tooth counts (3 … 1000): sun, planet 1 (meshes the sun), planet 2
            (meshes planet 1 and the ring), ring.
        stationary_efficiency : float, optional
            η0 in (0, 1], the efficiency with the carrier held; default 1
            (lossless) unless ``mesh_efficiencies`` are given.
        mesh_efficiencies : tuple of float, optional
            (sun–planet 1, planet 1–planet 2, planet 2–ring), each in (0, 1], combined by product into η0;
            not together with ``stationary_efficiency``.
        planets : int, default 3
            Number of planets (1 … 24): for the planet loads and the geometry.

        Returns
        -------
        PlanetarySet

        Raises
        ------
        ToothCountError
            A count that is not a whole number in range, a ring not larger than the
            sun or than planet 2, or planets that cannot be placed.
        EfficiencyError
            An efficiency outside (0, 1].
        ModelError
            Both ``stationary_efficiency`` and ``mesh_efficiencies``, the wrong number of
            mesh efficiencies, or shafts that are not three different names.

        References
        ----------
        Brandenberger 1952, eq. 1 (i0 as the product of the mesh ratios, carrier held:
        two external meshes and one internal give i0 = +z_ring/z_sun);
        SDP/SI, *Elements of Metric Gear Technology* (D785), section 13 (double planets).

        Examples
        --------
        >>> d = PlanetarySet.double_planet("D", sun="s", ring="r", carrier="c", z_sun=30,
        ...                                z_planet_sun=15, z_planet_ring=16, z_ring=78)
        >>> d.stationary_ratio, d.is_plus_set
        (2.6, True)
        """
        owner = f"planetary set {name!r}"
        zs = check_teeth(z_sun, "z_sun", owner)
        z1 = check_teeth(z_planet_sun, "z_planet_sun", owner)
        z2 = check_teeth(z_planet_ring, "z_planet_ring", owner)
        zr = check_teeth(z_ring, "z_ring", owner)
        if zr <= zs:
            raise ToothCountError(
                f"{owner}: the ring must have more teeth than the sun, got z_ring={zr}, z_sun={zs}."
            )
        teeth = Teeth("double", zs, zr, (z1, z2))
        check_double(teeth, owner)
        return cls(
            name, sun, ring, carrier, teeth.stationary_ratio,
            _combine(stationary_efficiency, mesh_efficiencies, 3, owner), planets, teeth,
        )

    @classmethod
    def stepped(
        cls,
        name: str,
        *,
        sun: str,
        ring: str,
        carrier: str,
        z_sun: int,
        z_planet_sun: int,
        z_planet_ring: int,
        z_ring: int,
        ring_internal: bool = True,
        sun_internal: bool = False,
        module_ratio: float | None = None,
        stationary_efficiency: float | None = None,
        mesh_efficiencies: tuple[float, ...] | None = None,
        planets: int = 3,
    ) -> PlanetarySet:
        """A stepped-planet set (Brandenberger's a/b·c/d).

        The first central gear a (``sun``) meshes planet gear b; planet gear
        c, on the same planet shaft, meshes the second central gear d
        (``ring``).  Each central gear is external or internal
        (``sun_internal``, ``ring_internal``):
        i0 = σ_a σ_d (z_d z_b)/(z_a z_c) with σ = −1 for an external and +1
        for an internal central gear (minus with one ring, plus with two suns
        or two rings).

        Parameters
        ----------
        name : str
            Element name (unique in the train).
        sun, ring, carrier : str
            The shafts of the first central gear a, the second central gear d
            and the carrier.
        z_sun, z_planet_sun, z_planet_ring, z_ring : int
            Tooth counts (3 … 1000) of a, b (meshes a), c (meshes d) and d.
        ring_internal : bool, default True
            Whether d is an internal gear (a ring); False for a second sun.
        sun_internal : bool, default False
            Whether a is an internal gear (True with ``ring_internal`` for a
            Wolfrom set: prefer :meth:`two_rings`).
        module_ratio : float, optional
            m_d/m_a, the module of the second mesh over that of the first.
            Given, the tooth counts are checked for coaxiality
            (|(z_a ± z_b) − (m_d/m_a)(z_d ± z_c)| ≤ 2 max(1, m_d/m_a) teeth);
            ``None`` (default) leaves coaxiality to the geometry
            (:func:`~epicyclic.geometry.check_coaxiality`).
        stationary_efficiency : float, optional
            η0 in (0, 1], the efficiency with the carrier held; default 1
            (lossless) unless ``mesh_efficiencies`` are given.
        mesh_efficiencies : tuple of float, optional
            (a–b, c–d), each in (0, 1], combined by product into η0;
            not together with ``stationary_efficiency``.
        planets : int, default 3
            Number of planets (1 … 24): for the planet loads and the geometry.

        Returns
        -------
        PlanetarySet

        Raises
        ------
        ToothCountError
            A count that is not a whole number in range, an internal gear not larger
            than its planet gear, i0 = 1 (two suns or two rings that lock), a
            non-positive ``module_ratio``, or counts that cannot be coaxial; also a
            ``ring_internal``/``sun_internal`` that is not a bool.
        EfficiencyError
            An efficiency outside (0, 1].
        ModelError
            Both ``stationary_efficiency`` and ``mesh_efficiencies``, the wrong number of
            mesh efficiencies, or shafts that are not three different names.

        References
        ----------
        Brandenberger 1952, eq. 1 and Bild 1–2: n2 − n3 = (n1 − n3)·(a/b)(c/d).

        Examples
        --------
        >>> s = PlanetarySet.stepped("B", sun="I", ring="II", carrier="III", z_sun=50,
        ...     z_planet_sun=24, z_planet_ring=30, z_ring=42, ring_internal=False)
        >>> round(s.stationary_ratio, 4)
        0.672
        """
        owner = f"planetary set {name!r}"
        zs = check_teeth(z_sun, "z_sun", owner)
        zb = check_teeth(z_planet_sun, "z_planet_sun", owner)
        zc = check_teeth(z_planet_ring, "z_planet_ring", owner)
        zr = check_teeth(z_ring, "z_ring", owner)
        for flag, value in (("ring_internal", ring_internal), ("sun_internal", sun_internal)):
            if not isinstance(value, bool):
                raise ToothCountError(f"{owner}: {flag} must be True or False, got {value!r}.")
        teeth = Teeth("stepped", zs, zr, (zb, zc), ring_internal, sun_internal)
        check_stepped(teeth, owner, module_ratio)
        return cls(
            name, sun, ring, carrier, teeth.stationary_ratio,
            _combine(stationary_efficiency, mesh_efficiencies, 2, owner), planets, teeth,
        )

    @classmethod
    def two_rings(
        cls,
        name: str,
        *,
        first: str,
        second: str,
        carrier: str,
        z_first: int,
        z_planet_first: int,
        z_planet_second: int,
        z_second: int,
        module_ratio: float | None = 1.0,
        stationary_efficiency: float | None = None,
        mesh_efficiencies: tuple[float, ...] | None = None,
        planets: int = 3,
    ) -> PlanetarySet:
        """A stepped set with two internal rings: the Wolfrom (3K) set, i0 = +(z_2 z_p1)/(z_1 z_p2).

        ``first`` and ``second`` are the shafts of the two rings (the set's
        ``sun`` and ``ring`` ports); ring 1 meshes planet gear ``z_planet_first``,
        ring 2 planet gear ``z_planet_second`` on the same planet shaft.  With
        equal modules (``module_ratio = 1``, default) the tooth counts must be
        coaxial: z_1 − z_p1 = z_2 − z_p2 within ±2 teeth.

        Parameters
        ----------
        name : str
            Element name (unique in the train).
        first, second, carrier : str
            The shafts of ring 1, ring 2 and the carrier.
        z_first, z_planet_first, z_planet_second, z_second : int
            Tooth counts (3 … 1000): ring 1, the planet gear meshing it, the planet
            gear meshing ring 2 (same planet shaft), ring 2.
        module_ratio : float or None, default 1.0
            m2/m1, the module of the ring-2 mesh over that of the ring-1 mesh, for the
            coaxiality check (z_1 − z_p1 = (m2/m1)(z_2 − z_p2) within ±2 max(1, m2/m1)
            teeth); ``None`` leaves coaxiality to the geometry.
        stationary_efficiency : float, optional
            η0 in (0, 1], the efficiency with the carrier held; default 1
            (lossless) unless ``mesh_efficiencies`` are given.
        mesh_efficiencies : tuple of float, optional
            (ring 1–planet, planet–ring 2), each in (0, 1], combined by product into η0;
            not together with ``stationary_efficiency``.
        planets : int, default 3
            Number of planets (1 … 24): for the planet loads and the geometry.

        Returns
        -------
        PlanetarySet

        Raises
        ------
        ToothCountError
            A count that is not a whole number in range, a ring not larger than its
            planet gear, z_1·z_p2 = z_2·z_p1 (i0 = 1: the set locks), a non-positive
            ``module_ratio`` or counts that cannot be coaxial.
        EfficiencyError
            An efficiency outside (0, 1].
        ModelError
            Both ``stationary_efficiency`` and ``mesh_efficiencies``, the wrong number of
            mesh efficiencies, or shafts that are not three different names.

        References
        ----------
        Brandenberger 1952, eq. 1 (a/b·c/d with both meshes internal: no sign change);
        SDP/SI D785, eq. (13-6) (equal centre distances).

        Examples
        --------
        A Wolfrom set: ring 1 (81 teeth) held, ring 2 (78) output, stepped planet 27/24:

        >>> w = PlanetarySet.two_rings("W", first="r1", second="r2", carrier="c", z_first=81,
        ...                            z_planet_first=27, z_planet_second=24, z_second=78)
        >>> round(w.stationary_ratio, 6), w.teeth.arrangement
        (1.083333, 'two rings')
        """
        return cls._two_central(name, True, first, second, carrier, (z_first, z_planet_first, z_planet_second,
                                z_second), module_ratio, stationary_efficiency, mesh_efficiencies, planets)

    @classmethod
    def two_suns(
        cls,
        name: str,
        *,
        first: str,
        second: str,
        carrier: str,
        z_first: int,
        z_planet_first: int,
        z_planet_second: int,
        z_second: int,
        module_ratio: float | None = 1.0,
        stationary_efficiency: float | None = None,
        mesh_efficiencies: tuple[float, ...] | None = None,
        planets: int = 3,
    ) -> PlanetarySet:
        """A stepped set with two external suns, i0 = +(z_2 z_p1)/(z_1 z_p2) (Brandenberger's Bild 1).

        With equal modules (``module_ratio = 1``, default) the tooth counts must
        be coaxial: z_1 + z_p1 = z_2 + z_p2 within ±2 teeth.

        Parameters
        ----------
        name : str
            Element name (unique in the train).
        first, second, carrier : str
            The shafts of sun 1 (Brandenberger's system I), sun 2 (system II) and
            the carrier (system III).
        z_first, z_planet_first, z_planet_second, z_second : int
            Tooth counts (3 … 1000): sun 1 (a), the planet gear meshing it (b), the
            planet gear meshing sun 2 (c, same planet shaft), sun 2 (d).
        module_ratio : float or None, default 1.0
            m2/m1, the module of the sun-2 mesh over that of the sun-1 mesh, for the
            coaxiality check (z_1 + z_p1 = (m2/m1)(z_2 + z_p2) within ±2 max(1, m2/m1)
            teeth); ``None`` leaves coaxiality to the geometry.
        stationary_efficiency : float, optional
            η0 in (0, 1], the efficiency with the carrier held; default 1
            (lossless) unless ``mesh_efficiencies`` are given.
        mesh_efficiencies : tuple of float, optional
            (sun 1–planet, planet–sun 2), each in (0, 1], combined by product into η0;
            not together with ``stationary_efficiency``.
        planets : int, default 3
            Number of planets (1 … 24): for the planet loads and the geometry.

        Returns
        -------
        PlanetarySet

        Raises
        ------
        ToothCountError
            A count that is not a whole number in range, z_1·z_p2 = z_2·z_p1 (i0 = 1:
            the set locks), a non-positive ``module_ratio`` or counts that cannot be
            coaxial.
        EfficiencyError
            An efficiency outside (0, 1].
        ModelError
            Both ``stationary_efficiency`` and ``mesh_efficiencies``, the wrong number of
            mesh efficiencies, or shafts that are not three different names.

        References
        ----------
        Brandenberger 1952, eq. 1 and Bild 1: n2 − n3 = (n1 − n3)·(a/b)(c/d).

        Examples
        --------
        >>> s = PlanetarySet.two_suns("B", first="I", second="II", carrier="III", z_first=50,
        ...                           z_planet_first=24, z_planet_second=30, z_second=42)
        >>> round(s.stationary_ratio, 4)
        0.672
        """
        return cls._two_central(name, False, first, second, carrier, (z_first, z_planet_first, z_planet_second,
                                z_second), module_ratio, stationary_efficiency, mesh_efficiencies, planets)

    @classmethod
    def _two_central(cls, name, internal, first, second, carrier, counts, module_ratio, stationary_efficiency,
                     mesh_efficiencies, planets) -> PlanetarySet:
        """A stepped set whose two central gears are both internal (rings) or both external (suns)."""
        owner = f"planetary set {name!r}"
        labels = ("z_first", "z_planet_first", "z_planet_second", "z_second")
        z1, zb, zc, z2 = (check_teeth(z, label, owner) for z, label in zip(counts, labels))
        teeth = Teeth("stepped", z1, z2, (zb, zc), ring_internal=internal, sun_internal=internal)
        check_stepped(teeth, owner, module_ratio, labels)
        return cls(
            name, first, second, carrier, teeth.stationary_ratio,
            _combine(stationary_efficiency, mesh_efficiencies, 2, owner), planets, teeth,
        )

    # ------------------------------------------------------------------ properties
    def _repr_html_(self) -> str:
        """Jupyter: a front view of the set and its key figures (:mod:`epicyclic.model.html`)."""
        from .html import planetary_set_html

        return planetary_set_html(self)

    @property
    def shafts(self) -> tuple[str, str, str]:
        """The joined shafts in port order (sun, ring, carrier)."""
        return (self.sun, self.ring, self.carrier)

    @property
    def is_plus_set(self) -> bool:
        """Whether i0 > 0 (central members turn the same way with the carrier held)."""
        return self.stationary_ratio > 0


def _combine(
    stationary_efficiency: float | None,
    mesh_efficiencies: tuple[float, ...] | None,
    meshes: int,
    owner: str,
) -> float:
    """η0 from either the stationary efficiency or the product of the mesh efficiencies."""
    if stationary_efficiency is not None and mesh_efficiencies is not None:
        raise ModelError(
            f"{owner}: give stationary_efficiency or mesh_efficiencies, not both."
        )
    if mesh_efficiencies is None:
        return 1.0 if stationary_efficiency is None else stationary_efficiency
    values = tuple(mesh_efficiencies)
    if len(values) != meshes:
        raise ModelError(
            f"{owner}: mesh_efficiencies must have {meshes} values (one per mesh in the "
            f"power path), got {len(values)}."
        )
    product = 1.0
    for k, value in enumerate(values):
        product *= check_efficiency(value, f"mesh_efficiencies[{k}]", owner)
    return product

"""``python -m epicyclic.demo``: solve the bundled Brandenberger 1952 example and print it.

References
----------
Brandenberger 1952, Beispiel to Bild 10.
"""

from __future__ import annotations

from . import GearStage, GearTrain, OperatingPoint, PlanetarySet, solve

#: Metric horsepower (PS) in W and the kilopond-centimetre in N·m.
PS = 735.49875
KP_CM = 0.0980665


def brandenberger_1952() -> tuple[GearTrain, OperatingPoint]:
    """The closed train of Brandenberger 1952, Bild 10, driven with 3 PS at 1500 1/min at II."""
    train = GearTrain(
        [
            PlanetarySet.stepped(
                "planetary", sun="I", ring="II", carrier="III", z_sun=50, z_planet_sun=24,
                z_planet_ring=30, z_ring=42, ring_internal=False, stationary_efficiency=0.9,
            ),
            GearStage.from_teeth("stage", "III", "II", [(40, 44, "external"), (20, 64, "external")], efficiency=0.9),
        ],
        name="Brandenberger 1952, Bild 10",
    )
    op = OperatingPoint(speeds={"II": 1500.0}, powers={"II": 3 * PS}, drives=["II"], loads=["I"])
    return train, op


def main() -> None:
    train, op = brandenberger_1952()
    solution = solve(train, op)
    print(solution.table())
    print()
    print(f"n1 = {solution.speed('I'):.0f} 1/min, n3 = {solution.speed('III'):.0f} 1/min, "
          f"eta' = {solution.efficiency:.4f}, output = {solution.output_power / PS:.3f} PS")


if __name__ == "__main__":
    main()

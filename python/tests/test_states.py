"""FMU states: restoring continues a run bit for bit, in place or from bytes in another instance."""
import numpy as np
import peristep
import pytest
from conftest import GLASS_CERAMIC


def opened(fmu):
    return peristep.Simulation(fmu=fmu, **GLASS_CERAMIC)


def test_restore_continues_bit_for_bit(fmu):
    with opened(fmu) as sim:
        sim.step(loadDisplacement=0.03e-6)
        state = sim.state()
        data = bytes(state)
        sim.step(loadDisplacement=0.05e-6)
        reference = sim.damage, sim.ux, sim.reactionForce, sim.time
        assert sim.brokenBonds > 0

        sim.restore(state)
        assert sim.time == state.time
        sim.step(loadDisplacement=0.05e-6)
        again = sim.damage, sim.ux, sim.reactionForce, sim.time
        state.free()
        state.free()  # twice is harmless
        with pytest.raises(peristep.PeriStepError):
            sim.restore(state)

    with opened(fmu) as other:  # another instance, never stepped: the bytes carry everything
        other.restore(data)
        other.step(loadDisplacement=0.05e-6)
        from_bytes = other.damage, other.ux, other.reactionForce, other.time
    for a, b, c in zip(reference, again, from_bytes):
        assert np.array_equal(a, b) and np.array_equal(a, c)


def test_close_frees_the_states(fmu):
    sim = opened(fmu)
    states = [sim.state() for _ in range(3)]
    sim.close()
    sim.close()
    assert all(s._handle is None for s in states)
    with pytest.raises(peristep.PeriStepError, match="freed"):
        bytes(states[0])


def test_a_corrupted_state_is_refused(fmu):
    with opened(fmu) as sim:
        data = bytearray(bytes(sim.state()))
        data[len(data) // 2] ^= 1
        with pytest.raises(peristep.PeriStepError, match="fmi3DeSerializeFMUState|fmi3DeserializeFMUState") as e:
            sim.restore(bytes(data))
        assert e.value.messages and "(the component logged no message)" not in e.value.messages

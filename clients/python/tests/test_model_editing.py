"""Models from scripts against a real server: a model's parameters and variables, replacing
its text, and structural editing over the WebSocket (with websocket-client; without it, the
ImportError that says what to install)."""
from __future__ import annotations

import importlib.util
import unittest

import tlmhub
from harness import ADMIN_PASSWORD, Server, expectation, shared_model

HAVE_WEBSOCKET = expectation("TLMHUB_EXPECT_WEBSOCKET", "websocket")
POSITION = "Mass#P2#Position"
VALVE = "4_3_Servo_Valve"

server: Server


def setUpModule() -> None:
    global server
    server = Server()


def tearDownModule() -> None:
    server.stop()


class Contents(unittest.TestCase):
    """parameters() and variables() read REST only: they work in both venvs."""

    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.model = cls.client.models.upload(shared_model())

    def test_parameters_name_values_as_runs_take_them(self):
        parameters = self.model.parameters()
        gain = parameters["GainP.k"]
        self.assertEqual((gain.value, gain.unit, gain.description, gain.type), ("0.0264249", "", "Gain", "double"))
        self.assertEqual((gain.component, gain.key), ("GainP", "k#Value"))
        self.assertAlmostEqual(gain.number, 0.0264249)
        mass = parameters["Mass.m"]
        self.assertEqual((mass.value, mass.unit, mass.description), ("100", "kg", "Mass"))
        self.assertEqual(parameters["Cylinder_C.A_1"].unit, "m^2")
        self.assertEqual(parameters["Tank_C.P1#Flow"].key, "P1#Flow")

    def test_parameters_by_id_equal_those_of_the_model(self):
        self.assertEqual(self.client.models.parameters(self.model.id), self.model.parameters())

    def test_every_listed_parameter_is_accepted_by_a_run(self):
        parameters = self.model.parameters()
        chosen = {name: parameters[name].number for name in ("GainP.k", "Mass.m", "Cylinder_C.A_1")}
        result = self.client.run(self.model, parameters=chosen, stop=0.05)
        self.assertIn(POSITION, result)

    def test_system_parameters_are_listed_by_their_own_name(self):
        text = shared_model().read_text().replace(
            "<parameters/>", '<parameters><parameter name="gain" value="0.03" type="double" '
            'unit="-" description="loop gain"/></parameters>', 1)
        self.assertNotEqual(text, shared_model().read_text())
        model = self.client.models.upload(text, name="servo with a system parameter")
        gain = model.parameters()["gain"]
        self.assertEqual((gain.value, gain.component, gain.description), ("0.03", "", "loop gain"))

    def test_variables_are_the_columns_of_a_run_with_units(self):
        jobs_before = [job.id for job in self.client.jobs.list()]
        variables = self.model.variables()
        # The run that told them leaves no job behind.
        self.assertEqual([job.id for job in self.client.jobs.list()], jobs_before)
        self.assertEqual(variables[POSITION], tlmhub.Variable(POSITION, "m"))
        self.assertEqual(variables["Mass#P2#Velocity"].unit, "m/s")
        self.assertEqual(variables["Tank_C#P1#Pressure"].unit, "Pa")
        self.assertEqual((variables[POSITION].component, variables[POSITION].port), ("Mass", "P2"))
        result = self.client.run(self.model, stop=0.01)
        self.assertEqual(sorted(variables), sorted(result.names))

    def test_update_replaces_the_text(self):
        model = self.client.models.upload(shared_model())
        changed = shared_model().read_text().replace("0.0264249", "0.031", 1)
        self.assertNotEqual(changed, shared_model().read_text())
        updated = self.client.models.update(model.id, changed)
        self.assertEqual(updated.id, model.id)
        self.assertEqual(self.client.models.hmf(model.id), changed)
        self.assertEqual(self.client.models.parameters(model.id)["GainP.k"].value, "0.031")

    def test_update_from_a_file_with_a_new_name(self):
        model = self.client.models.upload(shared_model().read_text().replace("0.0264249", "0.02", 1), name="old")
        updated = self.client.models.update(model.id, shared_model(), name="renamed servo")
        self.assertEqual(updated.name, "renamed servo")
        self.assertEqual(self.client.models.hmf(model.id), shared_model().read_text())

    def test_update_of_text_that_is_no_model_is_refused(self):
        model = self.client.models.upload(shared_model())
        with self.assertRaises(tlmhub.Refused) as caught:
            self.client.models.update(model.id, "<hopsanmodelfile>")
        self.assertEqual((caught.exception.status, caught.exception.code), (400, "invalid_model"))
        self.assertEqual(self.client.models.hmf(model.id), shared_model().read_text())


@unittest.skipUnless(HAVE_WEBSOCKET, "model editing: the venv with websocket-client")
class Editing(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)

    def setUp(self):
        self.model = self.client.models.upload(shared_model())

    def position(self, model: int | tlmhub.Model) -> list[float]:
        return list(self.client.run(model, stop=1.5)[POSITION])

    def test_an_added_and_connected_component_changes_the_run(self):
        before = self.position(self.model)
        # A leak from the supply to a new tank: less pressure, a slower servo.
        with self.client.models.edit(self.model.id) as editor:
            leak = editor.add("HydraulicLaminarOrifice", "Leak", x=100, y=50)
            tank = editor.add("HydraulicTankC", "Leak_Tank", x=150, y=50)
            editor.connect("Hydraulic_Volume_Multi_Port.P1", f"{leak}.P1")
            editor.connect(f"{leak}.P2", f"{tank}.P1")
            editor.set(f"{leak}.Kc", 1e-9)
            saved = editor.save()
        self.assertEqual((leak, tank), ("Leak", "Leak_Tank"))
        self.assertEqual(saved.id, self.model.id)
        self.assertEqual(self.model.parameters()["Leak.Kc"].number, 1e-9)
        self.assertIn("Leak#P2#Flow", self.model.variables())
        after = self.position(self.model)
        self.assertEqual(len(before), len(after))
        self.assertGreater(max(abs(a - b) for a, b in zip(before, after)), 0.01)

    def test_nothing_is_stored_without_save(self):
        with self.client.models.edit(self.model.id) as editor:
            editor.set("GainP.k", 0.05)
            self.assertEqual(editor.get("GainP.k").value, "0.05")
        self.assertEqual(self.client.models.hmf(self.model.id), shared_model().read_text())

    def test_set_names_parameters_as_runs_do(self):
        with self.client.models.edit(self.model.id) as editor:
            self.assertEqual(editor.set("GainP.k", 0.03).key, "k#Value")
            self.assertEqual(editor.set("Mass.m", "2*50").value, "2*50")
            editor.set_system_parameter("gain", 0.02, description="loop gain")
            self.assertEqual(editor.set("GainI.k", "gain").value, "gain")
            self.assertEqual(editor.set("gain", 0.001).value, "0.001")
            editor.save()
        stored = self.model.parameters()
        self.assertEqual((stored["GainP.k"].value, stored["Mass.m"].value, stored["GainI.k"].value),
                         ("0.03", "2*50", "gain"))
        self.assertEqual((stored["gain"].value, stored["gain"].description), ("0.001", "loop gain"))
        edited = self.position(self.model)
        overridden = self.position_with({"GainP.k": 0.03, "Mass.m": 100, "GainI.k": 0.001})
        self.assertEqual(edited, overridden)

    def position_with(self, parameters):
        original = self.client.models.upload(shared_model())
        return list(self.client.run(original, parameters=parameters, stop=1.5)[POSITION])

    def test_remove_drops_the_component_and_its_connections(self):
        with self.client.models.edit(self.model.id) as editor:
            editor.remove("Scope")
            structure = editor.model()["system"]
            editor.save()
        self.assertNotIn("Scope", [c["name"] for c in structure["components"]])
        ends = [e["component"] for c in structure["connections"] for e in (c["from"], c["to"])]
        self.assertNotIn("Scope", ends)
        self.assertNotIn("Scope.in_bottom", self.model.parameters())
        self.assertNotIn("Scope", {v.component for v in self.model.variables().values()})

    def test_rename_gives_the_name_the_server_chose_and_runs_follow(self):
        with self.client.models.edit(self.model.id) as editor:
            self.assertEqual(editor.rename("GainP", "Proportional gain"), "Proportional_gain")
            self.assertEqual(editor.rename("GainI", "Proportional_gain"), "Proportional_gain_1")
            editor.save()
        parameters = self.model.parameters()
        self.assertIn("Proportional_gain.k", parameters)
        self.assertNotIn("GainP.k", parameters)
        result = self.client.run(self.model, parameters={"Proportional_gain.k": 0.03}, stop=0.1)
        self.assertIn("Proportional_gain#out#Value", result)

    def test_disconnect_then_connect_again_gives_the_same_run(self):
        before = self.position(self.model)
        with self.client.models.edit(self.model.id) as editor:
            editor.disconnect("GainP.out", "Add.in1")
            editor.save()
        self.assertNotEqual(self.position(self.model), before)
        with self.client.models.edit(self.model.id) as editor:
            editor.connect(("Add", "in1"), ("GainP", "out"))
            editor.save()
        self.assertEqual(self.position(self.model), before)

    def test_replace_keeps_name_connections_and_parameters(self):
        before = self.position(self.model)
        with self.client.models.edit(self.model.id) as editor:
            editor.set(f"{VALVE}.d", 0.012)
            self.assertEqual(editor.replace(VALVE, "Hydraulic43ValveNeutralToTank"), VALVE)
            component = next(c for c in editor.model()["system"]["components"] if c["name"] == VALVE)
            editor.save()
        self.assertEqual(component["type"], "Hydraulic43ValveNeutralToTank")
        self.assertTrue(all(p["connected"] for p in component["ports"] if p["name"] in ("PP", "PT", "PA", "PB", "in")))
        self.assertEqual(self.model.parameters()[f"{VALVE}.d"].value, "0.012")
        self.assertNotEqual(self.position(self.model), before)

    def test_an_illegal_connection_raises_refused_with_the_servers_code(self):
        with self.client.models.edit(self.model.id) as editor:
            with self.assertRaises(tlmhub.Refused) as caught:
                editor.connect("Mass.P1", "Tank_C.P1")
        self.assertEqual((caught.exception.status, caught.exception.code), (0, "illegal_connection"))
        self.assertIn("Mass.P1", caught.exception.message)

    def test_refusals_keep_the_servers_code_and_kind(self):
        with self.client.models.edit(self.model.id) as editor:
            with self.assertRaises(tlmhub.Refused) as caught:
                editor.add("HydraulicTeapot")
            self.assertEqual(caught.exception.code, "unknown_component_type")
            with self.assertRaises(tlmhub.Refused) as caught:
                editor.set("GainP.k", "gian")
            self.assertEqual(caught.exception.code, "invalid_parameter")
            self.assertEqual(editor.get("GainP.k").value, "0.0264249")
            with self.assertRaises(tlmhub.NotFound) as caught:
                editor.remove("NoSuchComponent")
            self.assertEqual(caught.exception.code, "not_found")
            with self.assertRaises(tlmhub.NotFound):
                editor.set("GainP.no_such_parameter", 1)
            with self.assertRaises(tlmhub.NotFound):
                editor.set("no_such_system_parameter", 1)
            with self.assertRaises(tlmhub.Refused) as caught:
                editor.disconnect("GainP.out", "Mass.P1")
            self.assertEqual(caught.exception.code, "illegal_connection")

    def test_save_as_copy_leaves_the_original(self):
        with self.client.models.edit(self.model.id) as editor:
            editor.set("GainP.k", 0.02)
            copy = editor.save(as_copy=True, name="my servo")
            self.assertEqual(editor.model_id, copy.id)
        self.assertNotEqual(copy.id, self.model.id)
        self.assertEqual(copy.name, "my servo")
        self.assertEqual(copy.parameters()["GainP.k"].value, "0.02")
        self.assertEqual(self.model.parameters()["GainP.k"].value, "0.0264249")

    def test_an_unknown_model_is_not_found(self):
        with self.assertRaises(tlmhub.NotFound):
            self.client.models.edit(999999)


class WithoutWebsocket(unittest.TestCase):
    def test_the_environment_is_the_expected_one(self):
        self.assertEqual(importlib.util.find_spec("websocket") is not None, HAVE_WEBSOCKET)

    @unittest.skipIf(HAVE_WEBSOCKET, "the missing-module error: the venv without websocket-client")
    def test_edit_says_what_to_install(self):
        client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        model = client.models.upload(shared_model())
        with self.assertRaises(ImportError) as caught:
            model.edit()
        self.assertIn("websocket-client", str(caught.exception))
        self.assertIn("tlmhub[stream]", str(caught.exception))


if __name__ == "__main__":
    unittest.main()

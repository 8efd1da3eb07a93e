"""launch.substitutions and launch.frontend's one ``$(...)`` scanner: the ROS 2 markup's
substitutions are the Python API's objects, and a value means the same in XML, YAML and
Python (``$(env X)`` after ``<set_env>``, ``$(if)``)."""

from __future__ import annotations

from pathlib import Path

import pytest

from launch import LaunchContext
from launch.frontend.parse_substitution import parse_at, parse_substitution
from launch.substitutions import (
    EnvironmentVariable,
    IfElseSubstitution,
    LaunchConfiguration,
    PythonExpression,
    TextSubstitution,
)
from launch_foundation import CodeRefused, LaunchError
from launcher.loading import resolve
from launcher.scope import Options

ENV_AFTER_SET_ENV = {
    "xml": '<launch>\n<set_env name="LAUNCH_API_X" value="new"/>\n'
    '<log message="$(env LAUNCH_API_X unset)"/>\n</launch>\n',
    "yaml": "launch:\n- set_env: {name: LAUNCH_API_X, value: new}\n"
    "- log: {message: $(env LAUNCH_API_X unset)}\n",
    "py": "from launch import LaunchDescription\n"
    "from launch.actions import LogInfo, SetEnvironmentVariable\n"
    "from launch.substitutions import EnvironmentVariable\n\n\n"
    "def generate_launch_description():\n    return LaunchDescription([\n"
    "        SetEnvironmentVariable('LAUNCH_API_X', 'new'),\n"
    "        LogInfo(msg=EnvironmentVariable('LAUNCH_API_X', default_value='unset')),\n"
    "    ])\n",
}
SUFFIX = {"xml": ".launch.xml", "yaml": ".launch.yaml", "py": "_launch.py"}


@pytest.mark.parametrize("fmt", ["xml", "yaml", "py"])
def test_env_after_set_env_is_the_new_value_in_every_format(tmp_path, monkeypatch, fmt):
    monkeypatch.delenv("LAUNCH_API_X", raising=False)
    path = tmp_path / f"env{SUFFIX[fmt]}"
    path.write_text(ENV_AFTER_SET_ENV[fmt])
    assert resolve(path, {}, Options()).messages == ["new"]


IF_SUBSTITUTION = (
    '<launch>\n<arg name="sim" default="true"/>\n'
    "<log message=\"$(if $(var sim) 'simulated robot' 'real robot')\"/>\n"
    '<log message="$(if $(not $(var sim)) yes)"/>\n</launch>\n'
)


@pytest.mark.parametrize(("sim", "expected"), [("true", ["simulated robot", ""]),
                                               ("false", ["real robot", "yes"])])  # fmt: skip
def test_if_substitution_chooses_by_its_condition(tmp_path, sim, expected):
    path = tmp_path / "if.launch.xml"
    path.write_text(IF_SUBSTITUTION)
    assert resolve(path, {"sim": sim}, Options()).messages == expected


def test_if_substitution_with_a_bad_condition_is_one_line_at_its_line(tmp_path):
    path = tmp_path / "if.launch.xml"
    path.write_text('<launch>\n<log message="$(if maybe a b)"/>\n</launch>\n')
    with pytest.raises(LaunchError, match=rf"^{path}:2: \$\(if\) condition must be true"):
        resolve(path, {}, Options())


def test_the_scanner_makes_the_python_apis_substitutions():
    parts = parse_substitution("robot_$(env ROBOT_NAME 'r $(var n)')_$(if 1 a)")
    assert [type(part) for part in parts] == [
        TextSubstitution, EnvironmentVariable, TextSubstitution, IfElseSubstitution,
    ]  # fmt: skip
    env = parts[1]
    assert [type(part) for part in env.default_value] == [TextSubstitution, LaunchConfiguration]
    context = LaunchContext()
    context.launch_configurations["n"] = "7"
    context.environment.pop("ROBOT_NAME", None)
    assert "".join(part.perform(context) for part in parts) == "robot_r 7_a"


def test_quotes_escapes_and_nesting_as_launch_reads_them():
    context = LaunchContext()
    assert parse_substitution("'yes' $0")[0].perform(context) == "'yes' $0"
    (expression,) = parse_substitution(r'$(eval "\'a\' + \'b\'")')
    assert isinstance(expression, PythonExpression) and expression.perform(context) == "ab"
    escaped = parse_substitution(r"\$(env X) \(")
    assert "".join(part.perform(context) for part in escaped) == "$(env X) ("
    (inner,) = parse_substitution("$(env \"A_$(env 'B')\")")
    assert inner.name[1].name[0].perform(context) == "'B'"  # other quotes are plain inside


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("$(env X", "unterminated substitution"),
        ("$(nosuch a)", r"unknown substitution \$\(nosuch\); known here: .*\$\(if\)"),
        ("$(env 'X)", "unterminated quote"),
        ("$(env)", r"\$\(env\) takes 1 to 2 arguments, got 0"),
        ("$(var " * 60 + "x" + ")" * 60, "substitutions nested more than 50 deep"),
    ],
)
def test_text_the_scanner_cannot_read_is_one_line_naming_where(text, message):
    with pytest.raises(LaunchError, match=rf"^f\.launch\.xml:3: {message}"):
        parse_at(text, "f.launch.xml:3")


def test_a_frontends_command_and_code_need_allow_code(tmp_path):
    path = tmp_path / "code.launch.xml"
    path.write_text('<launch>\n<log message="$(eval \'__import__(&quot;os&quot;).getpid()\')"/>\n'
                    "</launch>\n")  # fmt: skip
    with pytest.raises(CodeRefused, match=":2: "):
        resolve(path, {}, Options())
    assert resolve(path, {}, Options(allow_code=True)).messages[0].isdigit()


def test_each_substitution_is_exposed_by_its_frontend_name():
    from launch.frontend.expose import substitution_parse_methods

    for name in ("var", "env", "eval", "command", "if", "not", "and", "or", "equals",
                 "not-equals", "anon", "dirname", "filename", "find-exec", "file-content",
                 "find-pkg-share", "find-pkg-prefix"):  # fmt: skip
        parse_substitution(f"$({name} a b)" if name in ("equals", "not-equals", "and", "or")
                           else "$(dirname)")  # fmt: skip
    parse_substitution("$(find-pkg-share x)")
    assert {"var", "env", "if", "find-pkg-share", "file-content"} <= set(substitution_parse_methods)


def test_launch_configuration_equals_and_python_expression_read_the_context():
    from launch.conditions import LaunchConfigurationEquals, LaunchConfigurationNotEquals

    context = LaunchContext()
    context.launch_configurations["mode"] = "sim"
    with pytest.warns(UserWarning, match="deprecated in ros2 launch"):
        assert LaunchConfigurationEquals("mode", "sim").evaluate(context)
        assert LaunchConfigurationNotEquals("mode", "real").evaluate(context)
        assert LaunchConfigurationEquals("other", None).evaluate(context)
    assert (
        PythonExpression(["'", LaunchConfiguration("mode"), "' == 'sim'"]).perform(context)
        == "True"
    )


def test_file_path_is_performed_relative_to_nothing_but_given(tmp_path: Path):
    from launch.substitutions import FileContent

    (tmp_path / "a.txt").write_text("hello")
    assert FileContent(str(tmp_path / "a.txt")).perform(LaunchContext()) == "hello"

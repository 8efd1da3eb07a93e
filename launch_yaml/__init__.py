"""launch_yaml: its YAMLLaunchDescriptionSource, for Python launch files that include YAML."""

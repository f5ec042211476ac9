"""The body spec: YAML text -> validated pydantic models -> plain core inputs."""

"""The Voilà server process that ``planner serve`` supervises (``python -m
planner.app.voila_server NOTEBOOK [Voilà options]``).

Voilà as shipped answers any ``Host`` header (it sets ``allow_remote_access``), which lets a
web page on another site reach the dashboard through DNS rebinding. Here every request
whose ``Host`` is not a loopback name or address is refused with 403 before any handler
runs — pages, kernels, websockets and static files alike.
"""

from __future__ import annotations

import ipaddress
import os
import re
import sys

import tornado.web

__all__ = ["POOL_HEADER", "is_loopback_host", "pool_is_warm"]

#: Host names that mean this machine.
LOOPBACK_NAMES = ("localhost", "localhost.localdomain")


def is_loopback_host(host_header: str) -> bool:
    """Whether a ``Host`` header names this machine (``127.0.0.1:8866``, ``[::1]``,
    ``localhost``).

    Examples
    --------
    >>> [is_loopback_host(h) for h in ("127.0.0.1:8866", "localhost", "[::1]:80")]
    [True, True, True]
    >>> [is_loopback_host(h) for h in ("evil.example", "10.0.0.2:8866", "")]
    [False, False, False]
    """
    match = re.match(r"^(.*?)(:\d+)?$", host_header or "")
    host = match.group(1) if match else ""
    if host.startswith("[") and host.endswith("]"):
        host = host[1:-1]
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return host.lower() in LOOPBACK_NAMES


#: The path answering with this server's instance id (set by ``planner serve``): how the
#: supervisor knows that the server answering on the port is its own.
INSTANCE_PATH = "/tls-planner/instance"
INSTANCE_ENV = "TLS_PLANNER_INSTANCE"


#: The header of the instance answer saying whether a page would open at once: ``warm``
#: when the pre-started kernel (Voilà's preheat pool) has run the dashboard, else
#: ``warming``.
POOL_HEADER = "X-TLS-Planner-Pool"


def pool_is_warm(kernel_manager: object) -> bool:
    """Whether every pre-started kernel of Voilà's pool has finished running its notebook
    (True when there is no pool: nothing to wait for)."""
    pools = getattr(kernel_manager, "_pools", None) or {}
    for pool in pools.values():
        for started in pool:  # a kernel started, then its notebook rendered
            if not started.done():
                return False
            if started.exception() is None and not started.result()["task"].done():
                return False
    return True


class _InstanceHandler(tornado.web.RequestHandler):
    def get(self) -> None:
        self.set_header("Content-Type", "text/plain")
        warm = pool_is_warm(self.application.settings.get("kernel_manager"))
        self.set_header(POOL_HEADER, "warm" if warm else "warming")
        self.write(os.environ.get(INSTANCE_ENV, ""))


class LoopbackApplication(tornado.web.Application):
    """A Tornado application that serves loopback ``Host`` names only."""

    def find_handler(self, request, **kwargs):  # type: ignore[override]
        if not is_loopback_host(request.host):
            return self.get_handler_delegate(
                request, tornado.web.ErrorHandler, {"status_code": 403}
            )
        if request.path == INSTANCE_PATH:
            return self.get_handler_delegate(request, _InstanceHandler)
        if not is_template_file(request.path):
            return self.get_handler_delegate(
                request, tornado.web.ErrorHandler, {"status_code": 404}
            )
        return super().find_handler(request, **kwargs)


#: Where Voilà serves its templates' static files: ``/voila/templates/<template>/static/…``.
TEMPLATE_PREFIX = "/voila/templates/"


def is_template_file(path: str) -> bool:
    """Whether a request's path, if it asks for a template's static file, asks for one
    Voilà's handler can answer: ``<template>/static/<file>`` once percent-decoded, with no
    ``..`` or empty segment and no control character (its handler asserts the form and
    fails with a 500 on another, e.g. an encoded ``..%2f``). Other paths pass.

    >>> is_template_file("/voila/templates/lab/static/voila.js")
    True
    >>> is_template_file("/voila/templates/lab/static/..%2f..%2fsecret")
    False
    """
    if not path.startswith(TEMPLATE_PREFIX):
        return True
    from urllib.parse import unquote

    rest = unquote(path[len(TEMPLATE_PREFIX) :])
    parts = rest.replace("\\", "/").split("/")
    return (
        len(parts) >= 3
        and parts[1] == "static"
        and all(p not in ("", ".", "..") for p in parts)
        and not any(ord(c) < 32 for c in rest)
    )


def skip_iri_grammar() -> None:
    """Keep jsonschema from importing ``rfc3987_syntax``: installed with Jupyter's
    ``jsonschema[format-nongpl]``, it builds some 35 Earley grammars when imported, for the
    "iri" and "iri-reference" formats alone — 2 of the 3.3 s the server takes to import
    (python-jsonschema/jsonschema#1428). No Jupyter schema uses those formats; jsonschema
    imports the module under ``suppress(ImportError)`` and, without it, leaves them
    unchecked."""
    sys.modules.setdefault("rfc3987_syntax", None)  # type: ignore[arg-type]


def main(argv: list[str]) -> None:
    skip_iri_grammar()
    from voila.app import Voila

    tornado.web.Application = LoopbackApplication  # Voilà builds its application from this name
    Voila.launch_instance(argv)


if __name__ == "__main__":
    main(sys.argv[1:])

"""Request-scoped dependencies shared by the routers."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Annotated

from fastapi import Depends, Request
from sqlalchemy.orm import Session, sessionmaker


def _session(request: Request) -> Iterator[Session]:
    factory: sessionmaker[Session] = request.app.state.sessions
    with factory() as session, session.begin():
        yield session


# "function" scope: the transaction commits before the response leaves, so a client that reads
# right after its save (the editor's autosave, then a reload) always sees it.
DbSession = Annotated[Session, Depends(_session, scope="function")]

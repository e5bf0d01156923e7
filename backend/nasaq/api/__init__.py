"""The HTTP side: the FastAPI application, its routers and how errors reach the client."""

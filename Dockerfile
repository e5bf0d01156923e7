# syntax=docker/dockerfile:1
# Nasaq image: the front end built with Node, served by the Python backend.

FROM node:20-bookworm-slim AS frontend
WORKDIR /src
COPY package.json package-lock.json ./
COPY frontend/package.json frontend/
RUN npm ci --no-audit --no-fund
COPY frontend/ frontend/
RUN npm run build -w frontend

FROM python:3.11-slim-bookworm AS app
ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PIP_DISABLE_PIP_VERSION_CHECK=1
WORKDIR /app
COPY backend/ backend/
RUN pip install --no-cache-dir --constraint backend/requirements.lock './backend[postgres]'
COPY --from=frontend /src/frontend/dist /app/frontend/dist
COPY examples/projects/ /app/examples/projects/
COPY examples/lessons/ /app/examples/lessons/
RUN useradd --system --uid 10001 --home-dir /app nasaq && mkdir /data && chown nasaq /data
USER nasaq
ENV NASAQ_HOST=0.0.0.0 \
    NASAQ_PORT=8000 \
    NASAQ_DATA_DIR=/data \
    NASAQ_FRONTEND_DIST=/app/frontend/dist \
    NASAQ_EXAMPLES_DIR=/app/examples/projects \
    NASAQ_LESSONS_DIR=/app/examples/lessons
EXPOSE 8000
VOLUME ["/data"]
HEALTHCHECK --interval=30s --timeout=5s --start-period=20s \
    CMD ["python", "-c", "import urllib.request; urllib.request.urlopen('http://127.0.0.1:8000/api/health', timeout=4)"]
CMD ["nasaq", "serve"]

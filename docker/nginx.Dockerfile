# nginx in front of the bezier-service replicas (docker/compose.yaml builds it; the
# configuration, docker/nginx.conf, is mounted read-only at /etc/nginx/nginx.conf).
# Debian's nginx-light, like every other dependency of the project; it runs as
# www-data and listens on 8080, so it needs no privileges.
FROM debian:bookworm-slim

RUN apt-get update \
 && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends nginx-light \
 && rm -rf /var/lib/apt/lists/* /var/log/apt /var/log/dpkg.log /etc/nginx/sites-enabled/*

USER www-data
EXPOSE 8080
# SIGQUIT is nginx's graceful shutdown (finish requests in progress, then exit).
STOPSIGNAL SIGQUIT
# -e stderr: the compiled-in error log (/var/log/nginx) is not writable by www-data.
ENTRYPOINT ["nginx", "-e", "stderr", "-g", "daemon off;"]

#!/usr/bin/python3
"""Offline checks of the deployment files under docker/, no engine or cluster needed.

  /usr/bin/python3 tests/container/validate_manifests.py [REPO_DIR]

Needs Debian's python3-yaml and python3-kubernetes (run with /usr/bin/python3, where apt
installs them). Checks:
  * docker/k8s/*.yaml against the Kubernetes API types of the python client: every field
    name known, every value of the declared type (autoscaling/v2 is checked against the
    v2beta2 types, its identical predecessor, as the client in Debian 12 predates v2);
  * the files agree with each other and with docker/Dockerfile: ports, probe paths,
    label selectors, the HPA's target, non-root uid, the shutdown time budget
    (preStop + drain + write timeout < terminationGracePeriodSeconds);
  * docker/compose.yaml: three replicas with health checks, nginx started only once they
    are healthy, and docker/nginx.conf's upstream naming exactly those replicas, retrying
    the next upstream on error/timeout/502/503 for POSTs too, with keep-alive upstream
    connections. `docker-compose config -q` and `nginx -t` run too when installed.
Exit status 0 when every check passes, 1 otherwise (each failure is printed).
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

try:
    import yaml
    from kubernetes import client
except ImportError as missing:
    sys.exit(f"FAIL: {missing}: install Debian's python3-yaml and python3-kubernetes "
             "and run with /usr/bin/python3")

REPO = os.path.abspath(sys.argv[1] if len(sys.argv) > 1
                       else os.path.join(os.path.dirname(__file__), "..", ".."))
DOCKER = os.path.join(REPO, "docker")
failures = []
passes = 0


def check(condition, what):
    global passes
    if condition:
        passes += 1
    else:
        failures.append(what)
        print(f"FAIL: {what}")
    return condition


def load_yaml(path):
    with open(path, encoding="utf-8") as f:
        return list(yaml.safe_load_all(f))


# ------------------------------------------------------------------ Kubernetes API types
PRIMITIVES = {"str": str, "int": int, "bool": bool, "float": (int, float)}


def walk(value, type_name, path, errors):
    """Checks value against the python client's openapi type name (recursively)."""
    if value is None:
        return
    if type_name.startswith("list["):
        if not isinstance(value, list):
            errors.append(f"{path}: expected a list")
            return
        for i, item in enumerate(value):
            walk(item, type_name[5:-1], f"{path}[{i}]", errors)
    elif type_name.startswith("dict("):
        if not isinstance(value, dict):
            errors.append(f"{path}: expected a mapping")
            return
        inner = type_name[5:-1].split(", ", 1)[1]
        for key, item in value.items():
            # Quantities (resources) may be written as plain numbers.
            if inner == "str" and isinstance(item, (int, float)) and not isinstance(item, bool):
                continue
            walk(item, inner, f"{path}.{key}", errors)
    elif type_name == "object":  # IntOrString and free-form fields
        if not isinstance(value, (str, int, dict, list)):
            errors.append(f"{path}: unexpected {type(value).__name__}")
    elif type_name in PRIMITIVES:
        wanted = PRIMITIVES[type_name]
        if isinstance(value, bool) and type_name != "bool" or not isinstance(value, wanted):
            errors.append(f"{path}: expected {type_name}, got {value!r}")
    else:
        model = getattr(client, type_name, None)
        if model is None:
            errors.append(f"{path}: unknown type {type_name}")
            return
        if not isinstance(value, dict):
            errors.append(f"{path}: expected a {type_name} mapping")
            return
        by_json = {json: attr for attr, json in model.attribute_map.items()}
        for key, item in value.items():
            if key not in by_json:
                errors.append(f"{path}.{key}: no such field in {type_name}")
                continue
            walk(item, model.openapi_types[by_json[key]], f"{path}.{key}", errors)


TOP_TYPES = {
    ("apps/v1", "Deployment"): "V1Deployment",
    ("v1", "Service"): "V1Service",
    ("autoscaling/v2", "HorizontalPodAutoscaler"):
        "V2HorizontalPodAutoscaler" if hasattr(client, "V2HorizontalPodAutoscaler")
        else "V2beta2HorizontalPodAutoscaler",
}


def quantity(text):
    """A Kubernetes resource quantity as a number (cores or bytes)."""
    text = str(text)
    suffixes = {"m": 1e-3, "k": 1e3, "M": 1e6, "G": 1e9, "Ki": 2**10, "Mi": 2**20, "Gi": 2**30}
    match = re.fullmatch(r"([0-9.]+)(m|k|M|G|Ki|Mi|Gi)?", text)
    if not match:
        raise ValueError(f"bad quantity {text}")
    return float(match.group(1)) * suffixes.get(match.group(2), 1)


# ------------------------------------------------------------------ Dockerfile
def dockerfile_runtime_stage(path):
    """Instructions of the last stage as (KEYWORD, argument text), continuations joined."""
    with open(path, encoding="utf-8") as f:
        text = re.sub(r"\\\n", " ", f.read())
    lines = [l.strip() for l in text.splitlines() if l.strip() and not l.strip().startswith("#")]
    stage = []
    for line in lines:
        keyword, _, rest = line.partition(" ")
        if keyword.upper() == "FROM":
            stage = []
        stage.append((keyword.upper(), rest.strip()))
    return stage


def env_of(instructions):
    env = {}
    for keyword, rest in instructions:
        if keyword == "ENV":
            for key, value in re.findall(r"(\w+)=(\"[^\"]*\"|\S+)", rest):
                env[key] = value.strip('"')
    return env


def main():
    runtime = dockerfile_runtime_stage(os.path.join(DOCKER, "Dockerfile"))
    keywords = {k for k, _ in runtime}
    image_env = env_of(runtime)
    user = next((r for k, r in runtime if k == "USER"), "")
    image_uid = user.split(":")[0]
    expose = [r for k, r in runtime if k == "EXPOSE"]
    check(image_uid.isdigit() and int(image_uid) != 0, f"Dockerfile USER is numeric non-root ({user!r})")
    check(expose == [image_env.get("BEZIER_PORT")], f"Dockerfile EXPOSE {expose} is BEZIER_PORT")
    check(image_env.get("BEZIER_HOST") == "0.0.0.0", "Dockerfile binds 0.0.0.0 by default")
    check("HEALTHCHECK" in keywords, "Dockerfile has a HEALTHCHECK")
    check(("STOPSIGNAL", "SIGTERM") in runtime, "Dockerfile STOPSIGNAL SIGTERM")
    check_k8s(int(image_uid) if image_uid.isdigit() else -1, image_env)
    check_compose(image_env)
    print(f"{passes} checks passed, {len(failures)} failed")
    return 1 if failures else 0


# ------------------------------------------------------------------ Kubernetes
def check_k8s(image_uid, image_env):
    docs = {}
    k8s_dir = os.path.join(DOCKER, "k8s")
    for name in sorted(os.listdir(k8s_dir)):
        if not name.endswith(".yaml"):
            continue
        for doc in load_yaml(os.path.join(k8s_dir, name)):
            key = (doc.get("apiVersion"), doc.get("kind"))
            type_name = TOP_TYPES.get(key)
            if not check(type_name is not None, f"{name}: known apiVersion/kind {key}"):
                continue
            errors = []
            walk(doc, type_name, f"{name}:{doc['kind']}", errors)
            for error in errors:
                check(False, error)
            check(not errors, f"{name}: {doc['kind']} matches the {type_name} schema")
            docs[doc["kind"]] = doc
    for kind in ("Deployment", "Service", "HorizontalPodAutoscaler"):
        check(kind in docs, f"docker/k8s has a {kind}")
    if len(docs) < 3:
        return
    deployment, service, hpa = docs["Deployment"], docs["Service"], docs["HorizontalPodAutoscaler"]
    pod = deployment["spec"]["template"]
    labels = pod["metadata"]["labels"]
    selector = deployment["spec"]["selector"]["matchLabels"]
    check(selector.items() <= labels.items(), "Deployment selector matches its pod labels")
    check(service["spec"]["selector"].items() <= labels.items(), "Service selector matches the pods")
    containers = pod["spec"]["containers"]
    check(len(containers) == 1, "one container per pod")
    container = containers[0]
    env = {e["name"]: e.get("value") for e in container.get("env", [])}
    ports = {p.get("name"): p["containerPort"] for p in container.get("ports", [])}
    port = int(env.get("BEZIER_PORT", image_env.get("BEZIER_PORT")))
    check(ports.get("http") == port, f"containerPort 'http' is BEZIER_PORT ({port})")
    target = service["spec"]["ports"][0]["targetPort"]
    check(target in ports or target == port, "Service targetPort is the container port")

    readiness, liveness = container.get("readinessProbe", {}), container.get("livenessProbe", {})
    check(readiness.get("httpGet", {}).get("path") == "/readyz", "readinessProbe GET /readyz")
    check(liveness.get("httpGet", {}).get("path") == "/healthz", "livenessProbe GET /healthz")
    for probe in (readiness, liveness):
        check(probe.get("httpGet", {}).get("port") in (port, "http"), "probe on the service port")

    resources = container.get("resources", {})
    for kind in ("cpu", "memory"):
        request = resources.get("requests", {}).get(kind)
        limit = resources.get("limits", {}).get(kind)
        if check(request is not None and limit is not None, f"{kind} request and limit set"):
            check(quantity(request) <= quantity(limit), f"{kind} request {request} <= limit {limit}")

    pod_security = pod["spec"].get("securityContext", {})
    security = container.get("securityContext", {})
    run_as = security.get("runAsUser", pod_security.get("runAsUser", image_uid))
    check(security.get("runAsNonRoot", pod_security.get("runAsNonRoot")) is True, "runAsNonRoot")
    check(run_as == image_uid and run_as != 0, f"runAsUser {run_as} is the image's uid {image_uid}")
    check(security.get("allowPrivilegeEscalation") is False, "allowPrivilegeEscalation false")

    # Shutdown budget: preStop sleep, then SIGTERM -> drain -> last writes, inside the grace.
    drain = float(env.get("BEZIER_DRAIN_SECONDS", image_env.get("BEZIER_DRAIN_SECONDS", 0)))
    write_timeout = float(env.get("BEZIER_WRITE_TIMEOUT", 5))
    pre_stop = container.get("lifecycle", {}).get("preStop", {}).get("exec", {}).get("command", [])
    pre_stop_s = float(pre_stop[1]) if len(pre_stop) == 2 and pre_stop[0] == "sleep" else 0.0
    grace = pod["spec"].get("terminationGracePeriodSeconds", 30)
    check(pre_stop_s > 0, "preStop sleeps before SIGTERM")
    check(drain > 0, "BEZIER_DRAIN_SECONDS set for the readiness drain")
    check(pre_stop_s + drain + write_timeout < grace,
          f"preStop {pre_stop_s} s + drain {drain} s + write {write_timeout} s < grace {grace} s")
    noticed = readiness.get("periodSeconds", 10) * readiness.get("failureThreshold", 3)
    check(noticed <= drain, f"readiness failure noticed ({noticed} s) within the drain ({drain} s)")

    ref = hpa["spec"]["scaleTargetRef"]
    check((ref["apiVersion"], ref["kind"], ref["name"]) ==
          ("apps/v1", "Deployment", deployment["metadata"]["name"]), "HPA targets the Deployment")
    check(1 <= hpa["spec"]["minReplicas"] <= hpa["spec"]["maxReplicas"], "HPA min <= max replicas")
    metrics = hpa["spec"].get("metrics", [])
    check(any(m.get("type") == "Resource" and m["resource"]["name"] == "cpu" for m in metrics),
          "HPA scales on CPU")


# ------------------------------------------------------------------ compose + nginx
def seconds(text):
    match = re.fullmatch(r"(\d+)(ms|s|m)?", str(text))
    scale = {"ms": 1e-3, "s": 1, "m": 60, None: 1}
    return float(match.group(1)) * scale[match.group(2)] if match else -1


def check_compose(image_env):
    path = os.path.join(DOCKER, "compose.yaml")
    compose = load_yaml(path)[0]
    services = compose.get("services", {})
    replicas = sorted(n for n, s in services.items()
                      if s.get("build", {}).get("dockerfile") == "docker/Dockerfile")
    check(len(replicas) == 3, f"compose: three service replicas ({replicas})")
    for name in replicas:
        s = services[name]
        context = os.path.normpath(os.path.join(DOCKER, s["build"]["context"]))
        check(os.path.isfile(os.path.join(context, s["build"]["dockerfile"])),
              f"compose: {name} builds an existing Dockerfile")
        check("bezier-healthcheck" in " ".join(s.get("healthcheck", {}).get("test", [])),
              f"compose: {name} has a health check")
        drain = float(s.get("environment", {}).get("BEZIER_DRAIN_SECONDS",
                                                   image_env.get("BEZIER_DRAIN_SECONDS", 0)))
        check(seconds(s.get("stop_grace_period", "10s")) > drain + 5,
              f"compose: {name} stop_grace_period covers drain + write timeout")
    nginx = services.get("nginx", {})
    depends = nginx.get("depends_on", {})
    check(all(depends.get(n, {}).get("condition") == "service_healthy" for n in replicas),
          "compose: nginx depends_on every replica being healthy")
    check(any(str(v).startswith("./nginx.conf:/etc/nginx/nginx.conf") for v in nginx.get("volumes", [])),
          "compose: nginx uses docker/nginx.conf")
    check(os.path.isfile(os.path.join(DOCKER, nginx.get("build", {}).get("context", "."),
                                      nginx.get("build", {}).get("dockerfile", "Dockerfile"))),
          "compose: nginx image Dockerfile exists")

    with open(os.path.join(DOCKER, "nginx.conf"), encoding="utf-8") as f:
        conf = re.sub(r"#[^\n]*", "", f.read())
    upstream = re.search(r"upstream\s+(\w+)\s*\{([^}]*)\}", conf)
    if not check(upstream is not None, "nginx.conf: an upstream block"):
        return
    ports = {n: services[n].get("environment", {}).get("BEZIER_PORT", image_env.get("BEZIER_PORT"))
             for n in replicas}
    servers = set(re.findall(r"^\s*server\s+(\S+?)[\s;]", upstream.group(2), re.M))
    check(servers == {f"{n}:{ports[n]}" for n in replicas},
          f"nginx.conf: upstream servers {sorted(servers)} are exactly the compose replicas")
    check(re.search(r"^\s*keepalive\s+\d+;", upstream.group(2), re.M) is not None,
          "nginx.conf: keep-alive connections to the upstreams")
    check(re.search(rf"proxy_pass\s+http://{upstream.group(1)}\s*;", conf) is not None,
          "nginx.conf: proxy_pass to the upstream")
    check(re.search(r"proxy_http_version\s+1\.1;", conf) and
          re.search(r'proxy_set_header\s+Connection\s+"";', conf),
          "nginx.conf: HTTP/1.1 with the Connection header cleared (needed for upstream keep-alive)")
    next_upstream = re.search(r"proxy_next_upstream\s+([^;]*);", conf)
    wanted = {"error", "timeout", "http_502", "http_503", "non_idempotent"}
    check(next_upstream is not None and wanted <= set(next_upstream.group(1).split()),
          "nginx.conf: proxy_next_upstream error timeout http_502 http_503 non_idempotent")

    if shutil.which("docker-compose"):
        result = subprocess.run(["docker-compose", "-f", path, "config", "-q"],
                                capture_output=True, text=True)
        check(result.returncode == 0, f"docker-compose config -q: {result.stderr.strip()}")
    else:
        print("note: docker-compose not installed, its schema check skipped")
    nginx_binary = shutil.which("nginx") or ("/usr/sbin/nginx" if os.path.exists("/usr/sbin/nginx") else None)
    if nginx_binary:
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(DOCKER, "nginx.conf"), encoding="utf-8") as f:
                text = f.read()
            for n in replicas:  # the compose names only resolve inside the compose network
                text = text.replace(f"server {n}:", "server 127.0.0.1:")
            test_conf = os.path.join(tmp, "nginx.conf")
            with open(test_conf, "w", encoding="utf-8") as f:
                f.write(text)
            result = subprocess.run([nginx_binary, "-t", "-q", "-e", "stderr", "-p", tmp, "-c", test_conf],
                                    capture_output=True, text=True)
            check(result.returncode == 0, f"nginx -t: {result.stderr.strip()}")
    else:
        print("note: nginx not installed, nginx -t skipped")


if __name__ == "__main__":
    sys.exit(main())

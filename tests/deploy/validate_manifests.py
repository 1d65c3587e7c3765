"""The Kubernetes manifests in deploy/kubernetes against the Kubernetes API schemas, offline
(kubernetes-validate bundles them; deploy/install-python-test-deps.sh installs the pinned one).
Every document must validate strictly (no unknown fields) for the Kubernetes version below; a
broken copy of one (a field in the wrong type, a made-up field) must not, so the check can fail.

    python3 tests/deploy/validate_manifests.py deploy/kubernetes
"""
import copy
import pathlib
import sys

# The oldest Kubernetes the manifests are for: native sidecars (initContainers with
# restartPolicy: Always) are on by default since 1.29; backoffLimitPerIndex since 1.29 (beta).
KUBERNETES_VERSION = "1.30.0"

try:
    import kubernetes_validate
    import yaml
except ImportError as e:
    sys.exit(f"{e}: install the test packages: deploy/install-python-test-deps.sh "
             "(kubernetes-validate, pinned in deploy/test-requirements.txt)")


def problems(document):
    """What is wrong with one manifest ("" when it validates)."""
    try:
        kubernetes_validate.validate(document, KUBERNETES_VERSION, strict=True)
        return ""
    except kubernetes_validate.ValidationError as e:
        return f"{'.'.join(str(p) for p in e.path)}: {e.message}"
    except kubernetes_validate.utils.SchemaNotFoundError as e:
        return f"no schema: {e}"


def main(folder):
    files = sorted(pathlib.Path(folder).glob("*.yaml"))
    if not files:
        sys.exit(f"no *.yaml in {folder}")
    failed, kinds = [], []
    for path in files:
        for document in yaml.safe_load_all(path.read_text()):
            if document is None:
                continue
            kinds.append(document["kind"])
            why = problems(document)
            print(f"{path.name}: {document['kind']} {document['metadata']['name']}: "
                  f"{why or 'valid'}")
            if why:
                failed.append(f"{path.name} {document['kind']}: {why}")
            if document["kind"] == "Deployment":
                deployment = document
    for kind in ("Namespace", "Secret", "StatefulSet", "Service", "Deployment", "Job"):
        if kind not in kinds:
            failed.append(f"no {kind} among the manifests")
    # The check can fail: a broken Deployment is refused.
    broken = copy.deepcopy(deployment)
    broken["spec"]["replicas"] = "three"
    broken["spec"]["template"]["spec"]["containers"][0]["livenessProbe"]["exec"]["cmd"] = ["x"]
    if not problems(broken):
        failed.append("a Deployment with replicas \"three\" and a made-up field validated")
    if failed:
        print("INVALID:\n  " + "\n  ".join(failed))
        return 1
    print(f"all {len(kinds)} manifests valid for Kubernetes {KUBERNETES_VERSION}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "deploy/kubernetes"))

#!/usr/bin/env python3
"""Downloads every artifact of a campaign from `rlpos-campaign serve` (see artifact_downloads.sh)
and compares each with the file `rlpos-campaign artifacts ID --out` exported: its bytes, and the
sha256 the API lists. Standard library only.

Exit 0 when every artifact matches; 1 with a one-line reason otherwise."""
import argparse
import hashlib
import json
import os
import sys
import urllib.request


def fail(message):
    print(f"FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def get(url):
    """The response's headers and its whole body (http.client raises IncompleteRead when the
    connection ends before Content-Length bytes)."""
    with urllib.request.urlopen(url, timeout=30) as response:
        return response.status, response.headers, response.read()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--url", required=True, help="the server's base URL")
    parser.add_argument("--campaign", required=True)
    parser.add_argument("--exported", required=True, help="the folder artifacts --out wrote")
    parser.add_argument("--count", type=int, required=True, help="the artifacts in the database")
    args = parser.parse_args()
    base = args.url.rstrip("/")

    status, _, body = get(f"{base}/api/campaigns/{args.campaign}")
    campaign = json.loads(body)
    listed = campaign["artifacts"]
    if campaign["artifacts_total"] != args.count or len(listed) != args.count:
        fail(f"the API lists {len(listed)} of {campaign['artifacts_total']} artifacts, "
             f"the database has {args.count}")
    exported = sum(len(files) for _, _, files in os.walk(args.exported))
    if exported != args.count:
        fail(f"artifacts --out wrote {exported} files for {args.count} artifacts")
    for artifact in listed:
        what = f"{artifact['job']}/{artifact['name']} ({artifact['url']})"
        try:
            status, headers, body = get(base + artifact["url"])
        except Exception as e:  # http.client.IncompleteRead: the body did not come whole
            fail(f"{what}: {type(e).__name__}: {e}")
        if status != 200:
            fail(f"{what}: status {status}")
        if int(headers["Content-Length"]) != len(body) or len(body) != artifact["bytes"]:
            fail(f"{what}: {len(body)} bytes, Content-Length {headers['Content-Length']}, "
                 f"listed {artifact['bytes']}")
        if "attachment" not in headers.get("Content-Disposition", ""):
            fail(f"{what}: no attachment header: {headers.get('Content-Disposition')}")
        digest = hashlib.sha256(body).hexdigest()
        if digest != artifact["sha256"]:
            fail(f"{what}: sha256 {digest}, the API lists {artifact['sha256']}")
        with open(os.path.join(args.exported, artifact["job"], artifact["name"]), "rb") as f:
            export = f.read()
        if export != body:
            fail(f"{what}: {len(body)} bytes downloaded differ from the {len(export)} exported "
                 f"(sha256 {hashlib.sha256(export).hexdigest()})")
    print(f"{len(listed)} artifacts downloaded, each byte-identical to artifacts --out's")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""A TLS-terminating proxy for tests: what a real deployment's proxy (nginx) does in front of
tlmhub-server, so clients can be tested against https:// and wss:// URLs.

    tls_proxy.py --backend 127.0.0.1:8080 --cert-dir DIR

makes a self-signed certificate for 127.0.0.1 and localhost in DIR (cert.pem, key.pem) with
Debian's openssl, listens on a free loopback port, prints "listening PORT" on stdout, and
forwards every connection's bytes to the backend in both directions until either side closes.
Clients trust DIR/cert.pem (SSL_CERT_FILE=DIR/cert.pem)."""
import argparse
import asyncio
import os
import ssl
import subprocess
import sys


def make_certificate(directory):
    cert = os.path.join(directory, "cert.pem")
    key = os.path.join(directory, "key.pem")
    subprocess.run(["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "2",
                    "-subj", "/CN=127.0.0.1", "-addext", "subjectAltName=IP:127.0.0.1,DNS:localhost",
                    "-keyout", key, "-out", cert], check=True, capture_output=True)
    return cert, key


async def pump(reader, writer):
    try:
        while True:
            data = await reader.read(65536)
            if not data:
                break
            writer.write(data)
            await writer.drain()
    except (ConnectionError, ssl.SSLError, asyncio.IncompleteReadError):
        pass
    finally:
        try:
            writer.close()
        except Exception:
            pass


async def serve(args):
    cert, key = make_certificate(args.cert_dir)
    context = ssl.create_default_context(ssl.Purpose.CLIENT_AUTH)
    context.load_cert_chain(cert, key)
    host, port = args.backend.rsplit(":", 1)

    async def handle(client_reader, client_writer):
        try:
            backend_reader, backend_writer = await asyncio.open_connection(host, int(port))
        except OSError:
            client_writer.close()
            return
        await asyncio.gather(pump(client_reader, backend_writer), pump(backend_reader, client_writer))

    server = await asyncio.start_server(handle, "127.0.0.1", 0, ssl=context)
    print("listening", server.sockets[0].getsockname()[1], flush=True)
    async with server:
        await server.serve_forever()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backend", required=True, help="HOST:PORT of the plain HTTP server")
    parser.add_argument("--cert-dir", required=True, help="where cert.pem and key.pem are written")
    try:
        asyncio.run(serve(parser.parse_args()))
    except KeyboardInterrupt:
        sys.exit(0)


if __name__ == "__main__":
    main()

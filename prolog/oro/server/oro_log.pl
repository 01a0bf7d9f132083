:- module(oro_log,
          [ oro_log_open/2,             % +File, +Options
            oro_log_reopen/0,
            oro_log_close/0,
            oro_log_request/5           % +Connection, +Peer, +Request, +Seconds, +Reply
          ]).
:- use_module(library(error)).
:- use_module(library(option)).
:- use_module(library(debug)).
:- use_module(library(oro/server/oro_protocol), [oro_encode_value/2]).

/** <module> The server's request log

With `--log=FILE` the server appends one line to FILE per request it
answers:

    2026-11-28T05:02:11.204Z conn=3 peer=127.0.0.1 method=find ms=0.41 ok
    2026-11-28T05:02:11.733Z conn=3 peer=127.0.0.1 method=getLabel ms=0.08 error=com.hp.hpl.jena.shared.NotFoundException

the time (UTC) the request was answered (the line is written before
the reply, so a client's requests are logged in the order it sent
them), the connection (numbered from 1
since the server started), the client's address, the method, the time
spent answering it and the outcome: `ok` or the ORO exception name.
The parameters (the payload) are never written unless asked with
`--log-payload`, as `params=` followed by them in JSON (or, for a
request prepared ahead, `args=` and the decoded arguments).  The one
line summaries of ontology loads (messages oro(...)) are written there
too, after the time.

oro_log_reopen/0 (on SIGHUP) closes the file and opens it again by its
name, so that a log rotation (rename, then SIGHUP) starts a new file
without losing a line.  The log is owned by this module: its stream is
written and replaced under the mutex `oro_log`.
*/

:- dynamic
    log/3.                              % Stream, File, Options

%!  oro_log_open(+File, +Options) is det.
%
%   Start writing the request log to File (appended to; created if
%   needed), replacing the log open now if any.  Options:
%
%     - payload(+Bool): also write each request's parameters (default
%       `false`).
%
%   @error permission_error(open, source_sink, File) if it cannot be
%   written.

oro_log_open(File, Options) :-
    must_be(atom, File),
    must_be(list, Options),
    option(payload(Payload), Options, false),
    must_be(boolean, Payload),
    open_log(File, Stream),
    with_mutex(oro_log,
               ( close_log,
                 assertz(log(Stream, File, [payload(Payload)]))
               )),
    debug(oro(log), 'Request log: ~w', [File]).

open_log(File, Stream) :-
    open(File, append, Stream, [encoding(utf8)]),
    set_stream(Stream, buffer(line)),
    set_stream(Stream, newline(posix)).

%!  oro_log_reopen is det.
%
%   Close the log and open it again by its name (after a log rotation).
%   Does nothing if there is no log.  If the file cannot be opened, the
%   error is printed and the log stays closed.

oro_log_reopen :-
    with_mutex(oro_log, reopen).

reopen :-
    (   retract(log(Stream, File, Options))
    ->  catch(close(Stream), _, true),
        catch(( open_log(File, New),
                assertz(log(New, File, Options))
              ),
              Error,
              print_message(error, Error))
    ;   true
    ).

%!  oro_log_close is det.
%
%   Stop writing the log and close its file.

oro_log_close :-
    with_mutex(oro_log, close_log).

close_log :-
    forall(retract(log(Stream, _, _)),
           catch(close(Stream), _, true)).

%!  oro_log_request(+Connection, +Peer, +Request, +Seconds, +Reply) is det.
%
%   Write the line of one request answered on Connection (an integer)
%   for the client at Peer (ip(A,B,C,D), or any term), if the log is
%   open.  Request is request(Method, Params) or prepared(Impl, Method,
%   Args); Reply is ok(_) or error(ExceptionName, Message).  A write
%   that fails is printed once and closes the log: requests are never
%   refused because of the log.

oro_log_request(Connection, Peer, Request, Seconds, Reply) :-
    (   log(_, _, _)
    ->  with_mutex(oro_log, log_request(Connection, Peer, Request,
                                        Seconds, Reply))
    ;   true
    ).

log_request(Connection, Peer, Request, Seconds, Reply) :-
    (   log(Stream, _, Options)
    ->  request_method(Request, Method),
        peer_text(Peer, PeerText),
        outcome(Reply, Outcome),
        Ms is Seconds * 1000,
        catch(( timestamp(Stream),
                format(Stream, " conn=~w peer=~w method=~w ms=~3f ~w",
                       [Connection, PeerText, Method, Ms, Outcome]),
                (   option(payload(true), Options)
                ->  payload(Stream, Request)
                ;   true
                ),
                nl(Stream)
              ),
              Error,
              log_failed(Error))
    ;   true
    ).

request_method(request(Method, _), Method).
request_method(prepared(_, Method, _), Method).

outcome(ok(_), ok).
outcome(error(Name, _), Outcome) :-
    format(atom(Outcome), 'error=~w', [Name]).

peer_text(ip(A, B, C, D), Text) :-
    !,
    format(atom(Text), '~w.~w.~w.~w', [A, B, C, D]).
peer_text(Peer, Text) :-
    format(atom(Text), '~q', [Peer]).

payload(Stream, request(_, Params)) :-
    !,
    oro_encode_value(list(Params), JSON),
    format(Stream, " params=~w", [JSON]).
payload(Stream, prepared(_, _, Args)) :-
    format(Stream, " args=~q", [Args]).

timestamp(Stream) :-
    get_time(Now),
    stamp_date_time(Now, Date, 'UTC'),
    format_time(Stream, '%FT%T.%3fZ', Date, posix).

log_failed(Error) :-
    close_log,
    print_message(error, Error).

%   The summary lines of oro's operator messages go to the log too.

:- multifile
    user:message_hook/3.

user:message_hook(oro(Message), Kind, Lines) :-
    Kind \== silent,
    \+ Message = ontology_loading(_, _, _),
    log(_, _, _),
    with_mutex(oro_log, log_message(Lines)),
    fail.

log_message(Lines) :-
    (   log(Stream, _, _)
    ->  catch(( timestamp(Stream),
                format(Stream, " ", []),
                print_message_lines(Stream, '', Lines)
              ),
              Error,
              log_failed(Error))
    ;   true
    ).

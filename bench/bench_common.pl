:- module(bench_common,
          [ bench_machine/0,
            bench_list_option/3,        % ?Option, +Options, +Default
            bench_with_server/4,        % +Args, -Port, -Pid, :Goal
            bench_with_connection/3,    % +Port, -Conn, :Goal
            bench_send/3,               % +Conn, +Method, +Params
            bench_receive/3,            % +Conn, -Message, +Timeout
            bench_call/3,               % +Conn, +Method, +Params
            bench_call/4,               % +Conn, +Method, +Params, ?Value
            bench_call/5,               % +Conn, +Method, +Params, ?Value, +Timeout
            bench_time/2,               % :Goal, -Micros
            bench_measure/5,            % +N, ?I, :Goal, :Prepare, -Times
            bench_summary/3,            % +Times, -Median, -P99
            bench_micros/2,             % +Micros, -Text
            bench_micros/3,             % +Micros, -Text, +Options
            bench_header/1,             % +SizeColumn
            bench_report/3,             % +Name, +Size, +Times
            bench_report/4,             % +Name, +Size, +Times, +Options
            bench_row/5,                % +Name, +Size, +Median, +P99, +PerSecond
            bench_row/6,                % +Name, +Size, +Median, +P99, +PerSecond, +Options
            bench_world/2,              % +Triples, -Statements
            bench_batches/3             % +List, +N, -Batches
          ]).
:- use_module(library(process)).
:- use_module(library(socket)).
:- use_module(library(readutil)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(predicate_options)).

:- meta_predicate
    bench_with_server(+, -, -, 0),
    bench_with_connection(+, -, 0),
    bench_time(0, -),
    bench_measure(+, ?, 0, 0, -).

:- predicate_options(bench_micros/3, 3,
                     [ units(oneof([us, auto]))
                     ]).
:- predicate_options(bench_report/4, 4,
                     [ pass_to(bench_row/6, 6)
                     ]).
:- predicate_options(bench_row/6, 6,
                     [ pass_to(bench_micros/3, 3)
                     ]).

/** <module> What the oro benchmarks share

The benchmarks in this directory (bench.pl, bench_events.pl,
bench_agents.pl, bench_sparql.pl, bench_categorization.pl) are
scripts; this module holds what they have in common:

  - the machine line printed first (SWI-Prolog version and CPU);
  - a command-line option taking one number or several
    (`--sizes=10000,100000`);
  - the real server, server/oro_server.pl, started as a child process
    on a free port and stopped afterwards;
  - a small socket client: send a request, read its `ok`, `error` or
    `event` message, optionally with a timeout;
  - timing a goal, N samples of it, their median and 99th percentile;
  - the common table (operation, size, median, p99, per second);
  - bench.pl's synthetic robot world, 4 triples an object.

The client is deliberately leaner than test/oro_test_client.pl: a
request waits for its reply with a blocking read unless a timeout is
given, so the socket figures measure the server, not the client.

Loading this module starts nothing.
*/

		 /*******************************
		 *           MACHINE            *
		 *******************************/

%!  bench_machine is det.
%
%   Print one line naming the SWI-Prolog version and the CPU model (from
%   `/proc/cpuinfo`, `unknown cpu` where there is none).

bench_machine :-
    current_prolog_flag(version, V),
    catch(( read_file_to_string('/proc/cpuinfo', CPU, []),
            sub_string(CPU, B, _, _, "model name"),
            sub_string(CPU, B, 80, _, L0),
            split_string(L0, "\n", "", [Line|_])
          ), _, Line = "unknown cpu"),
    format("SWI-Prolog ~w; ~w~n", [V, Line]).

%!  bench_list_option(?Option, +Options, +Default) is det.
%
%   Like option/3 for an option whose value is a list: Option is
%   Name(List).  The value from argv_options/3 (type `term`) may be one
%   term (`--sizes=1000`), a comma term (`--sizes=10,100`) or a list
%   (`--sizes=[10,100]`); a single term becomes a one-element list.
%   Default is the list used when Options has no such option.

bench_list_option(Option, Options, Default) :-
    functor(Option, Name, 1),
    arg(1, Option, List),
    functor(Given, Name, 1),
    (   option(Given, Options)
    ->  arg(1, Given, Term),
        term_list(Term, List)
    ;   List = Default
    ).

term_list(Term, List) :-
    (   is_list(Term)
    ->  List = Term
    ;   Term = (_,_)
    ->  comma_list(Term, List)
    ;   List = [Term]
    ).

		 /*******************************
		 *            SERVER            *
		 *******************************/

%!  bench_with_server(+Args, -Port, -Pid, :Goal) is semidet.
%
%   Run once(Goal) while the real server, `swipl
%   server/oro_server.pl --port=0` followed by the command-line
%   arguments Args, runs as a child process Pid listening on Port
%   (read from its first line, `oro listening on 127.0.0.1:Port`).  The
%   server is killed afterwards, whatever Goal did.
%
%   @error bench_no_port(Line) if the first line names no port.

bench_with_server(Args, Port, Pid, Goal) :-
    server_script(Server),
    setup_call_cleanup(
        process_create(path(swipl), [Server, '--port=0'|Args],
                       [stdout(pipe(Out)), process(Pid)]),
        ( read_line_to_string(Out, Line),
          server_port(Line, Port),
          once(Goal)
        ),
        ( catch(process_kill(Pid), _, true),
          process_wait(Pid, _),
          close(Out)
        )).

server_script(Server) :-
    module_property(bench_common, file(Here)),
    absolute_file_name('../server/oro_server.pl', Server,
                       [relative_to(Here), access(read)]).

server_port(Line, Port) :-
    (   string(Line),
        split_string(Line, ":", " ", Parts),
        last(Parts, PortText),
        number_string(Port, PortText)
    ->  true
    ;   throw(bench_no_port(Line))
    ).

		 /*******************************
		 *            CLIENT            *
		 *******************************/

%!  bench_with_connection(+Port, -Conn, :Goal) is semidet.
%
%   Run once(Goal) with Conn, a connection to the server on
%   127.0.0.1:Port (UTF-8, POSIX newlines), closed afterwards whatever
%   Goal did.  Conn is an opaque term for bench_send/3, bench_receive/3
%   and bench_call/3,4,5.

bench_with_connection(Port, Conn, Goal) :-
    setup_call_cleanup(
        connect(Port, Conn),
        once(Goal),
        disconnect(Conn)).

connect(Port, bench_conn(In, Out)) :-
    tcp_connect('127.0.0.1':Port, Pair, []),
    stream_pair(Pair, In, Out),
    set_stream(In, encoding(utf8)),
    set_stream(In, newline(posix)),
    set_stream(Out, encoding(utf8)),
    set_stream(Out, newline(posix)).

disconnect(bench_conn(In, Out)) :-
    catch(close(Out, [force(true)]), _, true),
    catch(close(In, [force(true)]), _, true).

%!  bench_send(+Conn, +Method, +Params) is det.
%
%   Send one request: Method, one line a parameter, then `#end#`.  A
%   parameter is
%
%     - a list, sent as a set `[a, b]` (its elements as they are);
%     - quoted(List), sent as a set of double-quoted elements
%       `["a", "b"]` with inner double quotes escaped, as liboro does,
%       so that commas inside an element are kept;
%     - anything else, written as it is (format `~w`).

bench_send(bench_conn(_, Out), Method, Params) :-
    format(Out, "~w~n", [Method]),
    forall(member(P, Params), write_param(Out, P)),
    format(Out, "#end#~n", []),
    flush_output(Out).

write_param(Out, quoted(List)) :-
    !,
    maplist(quoted_element, List, Elements),
    write_set(Out, Elements).
write_param(Out, List) :-
    is_list(List),
    !,
    write_set(Out, List).
write_param(Out, Text) :-
    format(Out, "~w~n", [Text]).

write_set(Out, Elements) :-
    atomic_list_concat(Elements, ', ', Text),
    format(Out, "[~w]~n", [Text]).

quoted_element(Text, Quoted) :-
    split_string(Text, "\"", "", Parts),
    atomic_list_concat(Parts, '\\"', Escaped),
    format(atom(Quoted), '"~w"', [Escaped]).

%!  bench_receive(+Conn, -Message, +Timeout) is det.
%
%   Read the server's next message: ok(Value), error(Name, Lines),
%   event(Id, Content), unexpected(First, Lines), or `timeout` when
%   nothing arrives within Timeout seconds.  With Timeout `infinite`
%   it is a plain blocking read.  Value, Id and Content are strings
%   (Value is `""` for a reply without a value line).
%
%   @error bench_connection_closed if the server closes the connection
%   within a message.

bench_receive(bench_conn(In, _), Message, Timeout) :-
    (   input_ready(In, Timeout)
    ->  read_line_to_string(In, First),
        message_body(In, Lines),
        message(First, Lines, Message)
    ;   Message = timeout
    ).

input_ready(_, infinite) :-
    !.
input_ready(In, Timeout) :-
    wait_for_input([In], [_], Timeout).

message_body(In, Lines) :-
    read_line_to_string(In, Line),
    (   Line == "#end#"
    ->  Lines = []
    ;   Line == end_of_file
    ->  throw(bench_connection_closed)
    ;   Lines = [Line|Rest],
        message_body(In, Rest)
    ).

message("ok", [Value], ok(Value)) :- !.
message("ok", [], ok("")) :- !.
message("error", [Name|Text], error(Name, Text)) :- !.
message("event", [Id, Content], event(Id, Content)) :- !.
message(First, Lines, unexpected(First, Lines)).

%!  bench_call(+Conn, +Method, +Params) is det.
%!  bench_call(+Conn, +Method, +Params, ?Value) is semidet.
%!  bench_call(+Conn, +Method, +Params, ?Value, +Timeout) is semidet.
%
%   Send a request (bench_send/3) whose next message must be its `ok`
%   reply, and unify Value with the reply's value; fails only if the
%   value does not unify.  Timeout (seconds or `infinite`, the default)
%   bounds the wait for the reply.  No event may be pending on Conn.
%
%   @error bench_failed(Method, Params, Reply) if the reply is not `ok`
%   (an error, an event, another message, or `timeout`).

bench_call(Conn, Method, Params) :-
    bench_call(Conn, Method, Params, _, infinite).

bench_call(Conn, Method, Params, Value) :-
    bench_call(Conn, Method, Params, Value, infinite).

bench_call(Conn, Method, Params, Value, Timeout) :-
    bench_send(Conn, Method, Params),
    bench_receive(Conn, Reply, Timeout),
    (   Reply = ok(Value0)
    ->  Value = Value0
    ;   throw(bench_failed(Method, Params, Reply))
    ).

		 /*******************************
		 *            TIMING            *
		 *******************************/

%!  bench_time(:Goal, -Micros) is semidet.
%
%   Run once(Goal); Micros is its wall-clock time in microseconds.
%   Fails if Goal fails.

bench_time(Goal, Micros) :-
    get_time(T0),
    once(Goal),
    get_time(T1),
    Micros is (T1 - T0) * 1.0e6.

%!  bench_measure(+N, ?I, :Goal, :Prepare, -Times) is det.
%
%   For I in 1..N, run once(Prepare), then time Goal with bench_time/2
%   (Prepare typically builds Goal's arguments from I).  Times are the
%   Goal's wall-clock times in microseconds, in order; a sample whose
%   Goal fails is left out.

bench_measure(N, I, Goal, Prepare, Times) :-
    findall(T, ( between(1, N, I),
                 once(Prepare),
                 bench_time(Goal, T)
               ), Times).

%!  bench_summary(+Times, -Median, -P99) is det.
%
%   The median and 99th percentile of a list of numbers: the elements
%   at N//2 and min(N-1, N*99//100) of the sorted list of N.  Both are
%   `-` for an empty list.

bench_summary([], -, -) :-
    !.
bench_summary(Times, Median, P99) :-
    msort(Times, Sorted),
    length(Sorted, N),
    M is N // 2,
    nth0(M, Sorted, Median),
    P is min(N - 1, (N * 99) // 100),
    nth0(P, Sorted, P99).

		 /*******************************
		 *            TABLES            *
		 *******************************/

%!  bench_micros(+Micros, -Text) is det.
%!  bench_micros(+Micros, -Text, +Options) is det.
%
%   Text shows a time in microseconds, `"12.3 us"`; it is `"-"` when
%   Micros is not a number.  Options:
%
%     - units(+Units)
%       `us` (default) always shows microseconds; `auto` shows
%       milliseconds (`"12.3 ms"`) from 10 ms on.

bench_micros(X, Text) :-
    bench_micros(X, Text, []).

bench_micros(X, Text, Options) :-
    option(units(Units), Options, us),
    (   \+ number(X)
    ->  Text = "-"
    ;   Units == auto,
        X >= 10000
    ->  format(string(Text), "~1f ms", [X/1000])
    ;   format(string(Text), "~1f us", [X])
    ).

%!  bench_header(+SizeColumn) is det.
%
%   Print the header of the common table: operation, SizeColumn (what
%   the second column counts), median, p99, per second.

bench_header(SizeColumn) :-
    format("~w~t~34|~w~t~12+~w~t~12+~w~t~12+~w~n",
           [operation, SizeColumn, median, p99, 'per second']).

%!  bench_report(+Name, +Size, +Times) is det.
%!  bench_report(+Name, +Size, +Times, +Options) is det.
%
%   Print a row of the common table for Times (microseconds, not
%   empty): their median, 99th percentile (bench_summary/3) and the
%   calls per second at the median.  Options as for bench_row/6.

bench_report(Name, Size, Times) :-
    bench_report(Name, Size, Times, []).

bench_report(Name, Size, Times, Options) :-
    bench_summary(Times, Median, P99),
    PerSecond is 1.0e6 / Median,
    bench_row(Name, Size, Median, P99, PerSecond, Options).

%!  bench_row(+Name, +Size, +Median, +P99, +PerSecond) is det.
%!  bench_row(+Name, +Size, +Median, +P99, +PerSecond, +Options) is det.
%
%   Print a row of the common table and flush.  Median and P99 are
%   microseconds (or `-`), shown by bench_micros/3 with Options;
%   PerSecond is a number or an arithmetic expression.

bench_row(Name, Size, Median, P99, PerSecond) :-
    bench_row(Name, Size, Median, P99, PerSecond, []).

bench_row(Name, Size, Median, P99, PerSecond0, Options) :-
    bench_micros(Median, MText, Options),
    bench_micros(P99, PText, Options),
    PerSecond is PerSecond0,
    format("~w~t~34|~d~t~12+~w~t~12+~w~t~12+~0f~n",
           [Name, Size, MText, PText, PerSecond]),
    flush_output.

		 /*******************************
		 *          THE WORLD           *
		 *******************************/

%!  bench_world(+Triples, -Statements) is det.
%
%   A synthetic robot world of about Triples triples, as strings in
%   oro's statement syntax: Triples//4 objects `objI`, each typed under
%   a common-sense class (Cup, Book, Box, Toy, Plate, VideoTape,
%   Bottle), on one of 50 pieces of furniture (`isOn furnitureF`, F is
%   I mod 50), coloured, and visible when I is even: 4 triples an
%   object.  The same Triples always give the same statements.

bench_world(Triples, Statements) :-
    Objects is Triples // 4,
    findall(S, ( between(1, Objects, I), object_statement(I, S) ),
            Statements).

object_statement(I, S) :-
    class(I, Class),
    F is I mod 50,
    color(I, Color),
    V is I mod 2,
    (   format(string(S), "obj~d rdf:type ~w", [I, Class])
    ;   format(string(S), "obj~d isOn furniture~d", [I, F])
    ;   format(string(S), "obj~d hasColor ~w", [I, Color])
    ;   V =:= 0
    ->  format(string(S), "obj~d isVisible true", [I])
    ;   format(string(S), "obj~d isVisible false", [I])
    ).

class(I, C) :-
    nth0(N, ['Cup', 'Book', 'Box', 'Toy', 'Plate', 'VideoTape', 'Bottle'], C),
    N =:= I mod 7,
    !.

color(I, C) :-
    nth0(N, [red, green, blue, yellow, black, white], C),
    N =:= I mod 6,
    !.

%!  bench_batches(+List, +N, -Batches) is det.
%
%   Batches are the consecutive slices of List of N elements, the last
%   one possibly shorter.

bench_batches(List, N, [Batch|Batches]) :-
    length(Batch, N),
    append(Batch, Rest, List),
    !,
    bench_batches(Rest, N, Batches).
bench_batches([], _, []) :-
    !.
bench_batches(List, _, [List]).

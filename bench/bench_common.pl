:- module(bench_common,
          [ bench_machine/0,
            bench_pin_to_cpu/1,         % +CPU
            bench_pin_option/1,         % +Options
            bench_cpus/1,               % -CPUs
            bench_set_cpus/1,           % +CPUs
            bench_list_option/3,        % ?Option, +Options, +Default
            bench_with_server/4,        % +Args, -Port, -Pid, :Goal
            bench_with_script/5,        % +Script, +Args, -Port, -Pid, :Goal
            bench_server_script/1,      % -File
            bench_stop_process/1,       % +Pid
            bench_memory/2,             % +Pid, -Memory
            bench_with_connection/3,    % +Port, -Conn, :Goal
            bench_send/3,               % +Conn, +Method, +Params
            bench_quoted/2,             % +Elements, -Quoted
            bench_receive/3,            % +Conn, -Message, +Timeout
            bench_call/3,               % +Conn, +Method, +Params
            bench_call/4,               % +Conn, +Method, +Params, ?Value
            bench_call/5,               % +Conn, +Method, +Params, ?Value, +Timeout
            bench_request/5,            % +Conn, +Method, +Params, -Reply, +Timeout
            bench_echo_start/2,         % +Port, -Echo
            bench_echo_stop/1,          % +Echo
            bench_time/2,               % :Goal, -Micros
            bench_measure/5,            % +N, ?I, :Goal, :Prepare, -Times
            bench_measure/6,            % +N, +Seconds, ?I, :Goal, :Prepare, -Times
            bench_measure/7,            % +N, +Seconds, ?I, :Goal, :Prepare, ?Template, -Samples
            bench_summary/3,            % +Times, -Median, -P99
            bench_stats/2,              % +Times, -Stats
            bench_micros/2,             % +Micros, -Text
            bench_micros/3,             % +Micros, -Text, +Options
            bench_header/1,             % +SizeColumn
            bench_report/3,             % +Name, +Size, +Times
            bench_report/4,             % +Name, +Size, +Times, +Options
            bench_row/5,                % +Name, +Size, +Median, +P99, +PerSecond
            bench_row/6,                % +Name, +Size, +Median, +P99, +PerSecond, +Options
            bench_world/2,              % +Triples, -Statements
            bench_object_statement/2,   % +I, -Statement
            bench_batches/3,            % +List, +N, -Batches
            bench_log_requests/2        % +File, -Requests
          ]).
:- use_module(library(process)).
:- use_module(library(socket)).
:- use_module(library(readutil)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(option)).
:- use_module(library(predicate_options)).
:- use_module(library(error)).
:- use_module(library(http/json)).

:- meta_predicate
    bench_with_server(+, -, -, 0),
    bench_with_script(+, +, -, -, 0),
    bench_with_connection(+, -, 0),
    bench_time(0, -),
    bench_measure(+, ?, 0, 0, -),
    bench_measure(+, +, ?, 0, 0, -),
    bench_measure(+, +, ?, 0, 0, ?, -).

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

The benchmarks in this directory (bench_full.pl and the focused ones
the README lists) are scripts; this module holds what they have in
common:

  - the machine line printed first (SWI-Prolog version and CPU);
  - a command-line option taking one number or several
    (`--sizes=10000,100000`);
  - the real server, server/oro_server.pl (or another script printing
    its port), started as a child process on a free port and stopped
    afterwards, and the memory of a child process (VmRSS, VmHWM);
  - a small socket client: send a request, read its `ok`, `error` or
    `event` message, optionally with a timeout, optionally skipping
    events;
  - the echo server, the floor of every socket figure: oro's framing
    and nothing else;
  - timing a goal, N samples of it (optionally within a time budget),
    their median, 99th percentile and maximum;
  - the common table (operation, size, median, p99, per second);
  - the synthetic robot world (bench_world/2), 4 triples an object;
  - the requests of a recorded ORO server log, to replay it.

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

%!  bench_pin_to_cpu(+CPU) is det.
%
%   Run every thread of this process, and so every process it starts
%   later (servers, the echo), on CPU only (taskset(1)).  A request and
%   its reply then never cross from one core to another: on a virtual
%   machine such a wake-up costs tens of microseconds, and whether the
%   scheduler puts a client and its server on the same core or not
%   differs from one process to the next, so figures are only
%   comparable when every process shares one core.

bench_pin_to_cpu(CPU) :-
    must_be(nonneg, CPU),
    bench_set_cpus(CPU).

%!  bench_pin_option(+Options) is det.
%
%   bench_pin_to_cpu/1 if Options (of argv_options/3) have pin(CPU), as
%   the benchmarks' `--pin=CPU` gives; nothing otherwise.

bench_pin_option(Options) :-
    (   option(pin(CPU), Options)
    ->  bench_pin_to_cpu(CPU)
    ;   true
    ).

%!  bench_set_cpus(+CPUs) is det.
%!  bench_cpus(-CPUs) is det.
%
%   Set, or get, the CPUs every thread of this process may run on, as
%   taskset(1) writes them (`0`, `0,1`, `0-3`).  Setting them also sets
%   them for the processes started later.

bench_set_cpus(CPUs) :-
    must_be(atomic, CPUs),
    current_prolog_flag(pid, Pid),
    process_create(path(taskset), ['-a', '-p', '-c', CPUs, Pid],
                   [stdout(null), process(Proc)]),
    process_wait(Proc, Status),
    (   Status == exit(0)
    ->  true
    ;   throw(error(bench_pin(CPUs, Status), _))
    ).

bench_cpus(CPUs) :-
    current_prolog_flag(pid, Pid),
    setup_call_cleanup(
        process_create(path(taskset), ['-p', '-c', Pid],
                       [stdout(pipe(Out))]),
        read_line_to_string(Out, Line),
        close(Out)),
    sub_string(Line, Before, _, _, ": "),
    !,
    Start is Before + 2,
    sub_string(Line, Start, _, 0, Text),
    atom_string(CPUs, Text).


		 /*******************************
		 *            SERVER            *
		 *******************************/

%!  bench_with_server(+Args, -Port, -Pid, :Goal) is semidet.
%
%   Run once(Goal) while the real server, `swipl
%   server/oro_server.pl --port=0 --http=0` followed by the command-line
%   arguments Args, runs as a child process Pid listening on Port
%   (read from its first line, `oro listening on 127.0.0.1:Port`).  The
%   server is stopped afterwards (bench_stop_process/1), whatever Goal
%   did.
%
%   @error bench_no_port(Line) if the first line names no port.

bench_with_server(Args, Port, Pid, Goal) :-
    bench_server_script(Server),
    bench_with_script(Server, ['--port=0', '--http=0'|Args], Port, Pid, Goal).

%!  bench_with_script(+Script, +Args, -Port, -Pid, :Goal) is semidet.
%
%   Run once(Goal) while `swipl Script Args...` runs as a child process
%   Pid whose first line on standard output ends with `:Port` (as the
%   server's `oro listening on 127.0.0.1:Port`).  The child is stopped
%   afterwards (bench_stop_process/1), whatever Goal did.
%
%   @error bench_no_port(Line) if the first line names no port.

bench_with_script(Script, Args, Port, Pid, Goal) :-
    setup_call_cleanup(
        process_create(path(swipl), [Script|Args],
                       [stdout(pipe(Out)), process(Pid)]),
        ( read_line_to_string(Out, Line),
          server_port(Line, Port),
          once(Goal)
        ),
        ( bench_stop_process(Pid),
          close(Out)
        )).

%!  bench_stop_process(+Pid) is det.
%
%   Stop the child process Pid and wait for it to end: SIGTERM; if it
%   still runs 10 s later, SIGINT; 10 s after that, SIGKILL.  Each step
%   beyond SIGTERM is reported on standard error.  A process may lose a
%   SIGTERM (with SWI-Prolog 9.0.4, one the kernel hands to a thread
%   that has not run yet; the server guards against it, see
%   server/oro_server.pl) or ignore SIGINT; a plain process_kill/1
%   followed by process_wait/2 would then wait forever.

bench_stop_process(Pid) :-
    stop_process([term, int, kill], Pid).

stop_process([Signal|Signals], Pid) :-
    catch(process_kill(Pid, Signal), _, true),
    (   exited_within(Pid, 10)
    ->  true
    ;   Signals = [Next|_]
    ->  upcase_atom(Signal, S),
        upcase_atom(Next, N),
        format(user_error, "Warning: process ~w still running 10 s after \c
                            SIG~w: sending SIG~w~n", [Pid, S, N]),
        stop_process(Signals, Pid)
    ;   process_wait(Pid, _)
    ).

%   exited_within(+Pid, +Seconds): Pid ended (and was waited for) within
%   Seconds.  process_wait/3's timeout(T) blocks until the end with
%   SWI-Prolog 9.0.4 unless T is 0, hence the polling.

exited_within(Pid, Seconds) :-
    get_time(Now),
    Deadline is Now + Seconds,
    exited_by(Pid, Deadline).

exited_by(Pid, Deadline) :-
    catch(process_wait(Pid, Status, [timeout(0)]), _, Status = gone),
    (   Status \== timeout
    ->  true
    ;   get_time(Now),
        Now < Deadline
    ->  sleep(0.05),
        exited_by(Pid, Deadline)
    ).

%!  bench_server_script(-File) is det.
%
%   File is the absolute path of server/oro_server.pl.

bench_server_script(Server) :-
    module_property(bench_common, file(Here)),
    absolute_file_name('../server/oro_server.pl', Server,
                       [relative_to(Here), access(read)]).

%!  bench_memory(+Pid, -Memory) is det.
%
%   Memory of the process Pid from `/proc/Pid/status`, as a dict
%   `memory{rss_kb:RSS, hwm_kb:HWM}`: its resident set now (VmRSS) and
%   at its peak (VmHWM), in kB.  A value that cannot be read is `-`.

bench_memory(Pid, memory{rss_kb:RSS, hwm_kb:HWM}) :-
    format(atom(File), '/proc/~w/status', [Pid]),
    (   catch(read_file_to_string(File, Status, []), _, fail)
    ->  status_kb(Status, "VmRSS:", RSS),
        status_kb(Status, "VmHWM:", HWM)
    ;   RSS = (-),
        HWM = (-)
    ).

status_kb(Status, Key, KB) :-
    split_string(Status, "\n", "", Lines),
    (   member(Line, Lines),
        string_concat(Key, Rest, Line),
        split_string(Rest, " \t", " \t", Parts),
        exclude(==(""), Parts, [Text|_]),
        number_string(KB0, Text)
    ->  KB = KB0
    ;   KB = (-)
    ).

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

%   nodelay: a request larger than the stream buffer goes out in
%   several writes, and Nagle's algorithm would hold the last one until
%   the server's delayed ACK (40 ms).

connect(Port, bench_conn(In, Out)) :-
    tcp_connect('127.0.0.1':Port, Pair, [nodelay(true)]),
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
    bench_quoted(List, Elements),
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

%!  bench_quoted(+Elements, -Quoted) is det.
%
%   Quoted are Elements double-quoted, inner double quotes escaped, as
%   liboro sends the elements of a set; a list of them is sent as it
%   is by bench_send/3.  (For a benchmark that times the server, not
%   the client's quoting.)

bench_quoted(Elements, Quoted) :-
    maplist(quoted_element, Elements, Quoted).

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

%!  bench_request(+Conn, +Method, +Params, -Reply, +Timeout) is det.
%
%   Send a request (bench_send/3) and read messages until its reply:
%   the first message that is not an event.  Reply is
%   reply(Message, Events): Message as of bench_receive/3 (`timeout` if
%   nothing but events came within Timeout seconds of the request) and
%   Events the number of events read before it.  For connections that
%   may receive events at any time, such as a replayed session.

bench_request(Conn, Method, Params, reply(Message, Events), Timeout) :-
    bench_send(Conn, Method, Params),
    (   Timeout == infinite
    ->  Deadline = infinite
    ;   get_time(Now),
        Deadline is Now + Timeout
    ),
    skip_events(Conn, Deadline, 0, Message, Events).

skip_events(Conn, Deadline, E0, Message, Events) :-
    (   Deadline == infinite
    ->  Left = infinite
    ;   get_time(Now),
        Left is max(0, Deadline - Now)
    ),
    bench_receive(Conn, Message0, Left),
    (   Message0 = event(_, _)
    ->  E1 is E0 + 1,
        skip_events(Conn, Deadline, E1, Message, Events)
    ;   Message = Message0,
        Events = E0
    ).

		 /*******************************
		 *         ECHO SERVER          *
		 *******************************/

%!  bench_echo_start(+Port, -Echo) is det.
%
%   Start the floor of the socket figures in this process: a trivial
%   server on 127.0.0.1:Port (0: a free port) with oro's framing and
%   none of its work.  An accept thread gives each connection a thread
%   of its own (TCP_NODELAY, UTF-8, as the real server); it reads lines
%   until `#end#` and answers every request `ok`, `true`, `#end#`.
%   Echo is a handle for bench_echo_stop/1; Echo.port is the port.

bench_echo_start(Port0, echo{port:Port, socket:Socket, accept:Accept}) :-
    must_be(nonneg, Port0),
    tcp_socket(Socket),
    tcp_setopt(Socket, reuseaddr),
    (   Port0 =:= 0
    ->  tcp_bind(Socket, '127.0.0.1':Port)
    ;   Port = Port0,
        tcp_bind(Socket, '127.0.0.1':Port)
    ),
    tcp_listen(Socket, 64),
    thread_create(echo_accept(Socket), Accept, []).

%!  bench_echo_stop(+Echo) is det.
%
%   Stop accepting connections and release the echo server's socket.
%   Connections in progress end when their clients close them.

bench_echo_stop(Echo) :-
    catch(thread_signal(Echo.accept, throw(bench_echo_stop)), _, true),
    thread_join(Echo.accept, _),
    catch(tcp_close_socket(Echo.socket), _, true).

echo_accept(Socket) :-
    catch(echo_accept_loop(Socket), bench_echo_stop, true).

echo_accept_loop(Socket) :-
    repeat,
    tcp_accept(Socket, Client, _Peer),
    thread_create(echo_connection(Client), _, [detached(true)]),
    fail.

echo_connection(Client) :-
    tcp_setopt(Client, nodelay),
    setup_call_cleanup(
        tcp_open_socket(Client, Pair),
        ( stream_pair(Pair, In, Out),
          set_stream(In, encoding(utf8)),
          set_stream(Out, encoding(utf8)),
          set_stream(Out, newline(posix)),
          catch(echo_requests(In, Out), _, true)
        ),
        close(Pair, [force(true)])).

echo_requests(In, Out) :-
    read_line_to_string(In, Line),
    (   Line == end_of_file
    ->  true
    ;   Line == "#end#"
    ->  format(Out, "ok~ntrue~n#end#~n", []),
        flush_output(Out),
        echo_requests(In, Out)
    ;   echo_requests(In, Out)
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

%!  bench_measure(+N, +Seconds, ?I, :Goal, :Prepare, -Times) is det.
%
%   As bench_measure/5, but stop taking samples once Seconds have
%   passed and at least 20 samples (or N, if fewer) were taken: slow
%   operations on large stores get fewer samples instead of holding
%   up the run.

bench_measure(N, Seconds, I, Goal, Prepare, Times) :-
    bench_measure(N, Seconds, I, Goal, Prepare, -, Samples),
    pairs_values(Samples, Times).

%!  bench_measure(+N, +Seconds, ?I, :Goal, :Prepare, ?Template, -Samples) is det.
%
%   As bench_measure/6, but Samples are Template-Micros, one for each
%   sample whose Goal succeeded, in order, with Template as Prepare and
%   Goal left it: a record of what each timed sample did (the statement
%   it added, for instance).

bench_measure(N, Seconds, I, Goal, Prepare, Template, Samples) :-
    get_time(T0),
    Deadline is T0 + Seconds,
    findall(Template-T,
            ( between(1, N, I),
              (   I > 20,
                  get_time(Now),
                  Now > Deadline
              ->  !,
                  fail
              ;   true
              ),
              once(Prepare),
              bench_time(Goal, T)
            ), Samples).

%!  bench_stats(+Times, -Stats) is det.
%
%   Stats summarises a list of times (microseconds) as a dict
%   `stats{n:N, median:Median, p99:P99, max:Max}`, the median and
%   99th percentile as of bench_summary/3; for an empty list N is 0 and
%   the others are `-`.

bench_stats([], stats{n:0, median:(-), p99:(-), max:(-)}) :-
    !.
bench_stats(Times, stats{n:N, median:Median, p99:P99, max:Max}) :-
    length(Times, N),
    bench_summary(Times, Median, P99),
    max_list(Times, Max).

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
    findall(S, ( between(1, Objects, I), bench_object_statement(I, S) ),
            Statements).

%!  bench_object_statement(+I, -Statement) is multi.
%
%   The four statements of the object `objI` of bench_world/2, one a
%   solution; for I beyond the world's objects, those of a new object.

bench_object_statement(I, S) :-
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

		 /*******************************
		 *        RECORDED LOGS         *
		 *******************************/

%!  bench_log_requests(+File, -Requests) is det.
%
%   Requests are the requests of a recorded ORO server log (such as
%   ../shared/workloads/robot-session-2011.log), in order: one
%   request(Thread, Method, Params) for each `[thread N] >> Got
%   incoming request: Method(Args)` line.  Thread is the text of the
%   thread tag (`""` if there is none), Method a string and Params the
%   arguments, each written back as one JSON line: a parameter as
%   bench_send/3 sends it.  The arguments are JSON-like literals; a
%   line whose arguments do not parse is bad(Line).

bench_log_requests(File, Requests) :-
    read_file_to_string(File, Text, [encoding(utf8)]),
    split_string(Text, "\n", "\r", Lines),
    convlist(log_request, Lines, Requests).

log_request(Line, Request) :-
    sub_string(Line, _, _, After, "Got incoming request: "),
    !,
    sub_string(Line, _, After, 0, Call),
    (   log_thread(Line, Thread0)
    ->  Thread = Thread0
    ;   Thread = ""
    ),
    (   sub_string(Call, Open, 1, _, "("),
        !,
        sub_string(Call, 0, Open, _, Method),
        string_concat(Head, ")", Call),
        ArgsStart is Open + 1,
        sub_string(Head, ArgsStart, _, 0, ArgsText),
        atomic_list_concat(['[', ArgsText, ']'], JSON),
        catch(atom_json_term(JSON, Args, [value_string_as(string)]), _, fail),
        is_list(Args),
        maplist(json_line, Args, Params)
    ->  Request = request(Thread, Method, Params)
    ;   Request = bad(Line)
    ).

log_thread(Line, Thread) :-
    sub_string(Line, B, _, _, "[thread "),
    !,
    Start is B + 8,
    sub_string(Line, Start, _, 0, Rest),
    sub_string(Rest, L, _, _, "]"),
    !,
    sub_string(Rest, 0, L, _, Thread).

json_line(Arg, Line) :-
    with_output_to(string(Line),
                   json_write(current_output, Arg, [width(0)])),
    \+ sub_string(Line, _, _, _, "\n").
